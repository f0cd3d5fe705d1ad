// Sunlight arriving at radius r: the transmittance to the top, or nothing
// when the planet stands between the point and the sun (its shadow;
// Hillaire 2020, sec. 5.2). By the including technique's
// transmittance_lookup(IN(Atmosphere), Real r, Real mu), declared before
// this file: a LUT on the GPU, a direct integral on the CPU.
//
// Below the bottom sphere (the air in a hollow under the datum, which the
// techniques march at the bottom's density: density.glsl) the sun's path
// first rises to the sphere through that air, then goes on to the top;
// there the terrain's shadow, not the sphere's, decides what the sun sees.
Real3 sun_visibility(IN(Atmosphere) atmosphere, Real r, Real mu_s) {
  Real bottom = atmosphere.bottom_radius;
  if (r < bottom) {
    Real rise = -r * mu_s + safe_sqrt(r * r * (mu_s * mu_s - Real(1.0)) + bottom * bottom);
    Real mu_bottom = clamp_cosine((r * mu_s + rise) / bottom);
    return exp(-extinction_at(atmosphere, Real(0.0)) * rise) *
           transmittance_lookup(atmosphere, bottom, mu_bottom);
  }
  return ray_intersects_ground(atmosphere, r, mu_s) ? Real3(0.0)
                                                    : transmittance_lookup(atmosphere, r, mu_s);
}
