// Texel-centred coordinates (Bruneton 2017, section 4): a unit range
// mapped so that texel centres sit at 0.5 / n and 1 - 0.5 / n and the
// extremes are sampled exactly; and the sun-zenith mapping that packs
// texels around the terminator (the shared math: see definitions.glsl).
Real texture_coord_from_unit_range(Real x, Real texture_size) {
  return Real(0.5) / texture_size + x * (Real(1.0) - Real(1.0) / texture_size);
}

Real unit_range_from_texture_coord(Real u, Real texture_size) {
  return (u - Real(0.5) / texture_size) / (Real(1.0) - Real(1.0) / texture_size);
}

// The sun's zenith cosine mu_s -> [0, 1] as (1 + sign(mu_s) sqrt(|mu_s|)) / 2,
// and back: packs samples around the terminator (mu_s = 0), where the light
// at a point changes fastest. Hillaire's multiple-scattering LUT and the
// ground's sky-irradiance table use it.
Real sky_irradiance_u_from_mu_s(Real mu_s) {
  Real m = clamp(mu_s, Real(-1.0), Real(1.0));
  return Real(0.5) + Real(0.5) * sign(m) * sqrt(abs(m));
}

Real mu_s_from_sky_irradiance_u(Real x) {
  Real s = Real(2.0) * x - Real(1.0);
  return s * abs(s);
}
