// Optical depth and transmittance to the top of the atmosphere: by
// quadrature, in closed form for one exponential layer, and the
// transmittance LUT's parameterisation (the shared math: see
// definitions.glsl; lut_coordinates.glsl and lut_sizes.glsl come first).

// --- Optical depth ----------------------------------------------------------
// Numerical optical depth from radius r along zenith cosine mu to the top
// boundary, per channel: the trapezoid rule over `steps` intervals of u,
// with the sample at distance t = L u^2 (L the distance to the top). The
// samples crowd near the start, where the air is densest on any ray that
// does not dip below its start's altitude by much; on Earth, 40 uniform
// steps put 0.018 too much optical depth on a ray 2 deg above the horizon
// (transmittance 1-2 % low at sunset), 40 of these 0.0044 at worst.
//
// Sample i (1 to steps) of that rule on the path of length L: the altitude
// there, and its weight, which the sum times L / steps turns into dt.
Real path_to_top_sample(IN(Atmosphere) atmosphere, Real r, Real mu, Real length_to_top, int i,
                        int steps, OUT(Real) weight) {
  Real u = Real(i) / Real(steps);
  Real t = length_to_top * u * u;
  // dt = 2 L u du; the sample at u = 0 has weight 0.
  weight = (i == steps ? Real(0.5) : Real(1.0)) * Real(2.0) * u;
  // Law of cosines: radius at distance t along the ray.
  return sqrt(t * t + Real(2.0) * r * mu * t + r * r) - atmosphere.bottom_radius;
}

Real3 optical_depth_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  Real length_to_top = distance_to_top_boundary(atmosphere, r, mu);
  Real3 sum = Real3(0.0);
  for (int i = 1; i <= steps; ++i) {
    Real weight;
    Real altitude = path_to_top_sample(atmosphere, r, mu, length_to_top, i, steps, weight);
    sum += weight * extinction_at(atmosphere, altitude);
  }
  return sum * (length_to_top / Real(steps));
}

Real3 transmittance_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  return exp(-optical_depth_to_top(atmosphere, r, mu, steps));
}

// --- Analytic optical depth of one exponential layer ---------------------------
// e^(x^2) erfc(x) for x >= 0: Numerical Recipes' Chebyshev fit of erfc
// (Press et al. 2007, section 6.2.2, fractional error below 1.2e-7), which
// is already the scaled form t exp(P(t)), so it never overflows.
Real erfcx(Real x) {
  Real t = Real(1.0) / (Real(1.0) + Real(0.5) * x);
  Real p = Real(-1.26551223) +
           t * (Real(1.00002368) +
           t * (Real(0.37409196) +
           t * (Real(0.09678418) +
           t * (Real(-0.18628806) +
           t * (Real(0.27886807) +
           t * (Real(-1.13520398) +
           t * (Real(1.48851587) + t * (Real(-0.82215223) + t * Real(0.17087277)))))))));
  return t * exp(p);
}

// The integral of exp(-(|x(t)| - r_ref) / H) along the ray from radius r
// with zenith cosine mu >= 0 to infinity (Chapman 1931's grazing-incidence
// integral, divided out as H exp(-(r - r_ref) / H) Ch). With z = H u the
// height gained, the exact integral is
//   H e^(-(r - r_ref)/H) int_0^inf e^-u (x + u) / sqrt(x^2 mu^2 + 2 x u + u^2) du,
// x = r / H. Expanding 1 / sqrt(a + u^2), a = 2 x (c + u), c = x mu^2 / 2, to
// first order in 1/x leaves three incomplete gamma integrals:
//   sqrt(x/2) G(1/2) + (G(3/2) - c G(1/2)) / sqrt(2x)
//   - (G(3/2) - 2 c G(1/2) + c^2 G(-1/2)) / (4 sqrt(2x)),
// with G(s) = e^c Gamma(s, c): G(1/2) = sqrt(pi) erfcx(sqrt c),
// G(3/2) = G(1/2) / 2 + sqrt c, c^2 G(-1/2) = 2 c (sqrt c - c G(1/2)).
// The leading term alone is the classic erfc form of the Chapman function,
// off by O(1/x) (1e-3 for Earth's Rayleigh layer); the neglected terms are
// O(1/x^2), below 1e-5 for Earth.
Real chapman_optical_depth_to_infinity(Real r_ref, Real scale_height, Real r, Real mu) {
  Real x = r / scale_height;
  Real c = Real(0.5) * x * mu * mu;
  Real y = sqrt(c);
  Real g_half = sqrt(kPi) * erfcx(y);
  Real g_three_halves = Real(0.5) * g_half + y;
  Real c2_g_minus_half = Real(2.0) * c * (y - c * g_half);
  Real inv_sqrt_2x = Real(1.0) / sqrt(Real(2.0) * x);
  Real sum = sqrt(Real(0.5) * x) * g_half + (g_three_halves - c * g_half) * inv_sqrt_2x -
             Real(0.25) * inv_sqrt_2x * (g_three_halves - Real(2.0) * c * g_half + c2_g_minus_half);
  return scale_height * exp(-(r - r_ref) / scale_height) * sum;
}

// The integral of density exp(-altitude / H) from radius r along zenith
// cosine mu to the top boundary, for a ray that does not meet the ground
// (multiply by a coefficient for optical depth). The part beyond the top is
// subtracted; a downward ray is split at its perigee r_p = r sqrt(1 - mu^2),
// where it is horizontal, into two upward halves.
Real exponential_optical_depth_to_top(IN(Atmosphere) atmosphere, Real scale_height, Real r,
                                      Real mu) {
  Real R = atmosphere.bottom_radius;
  Real top = atmosphere.top_radius;
  // At the exit point r_top mu_top = r mu + d (d the distance travelled).
  Real d = distance_to_top_boundary(atmosphere, r, mu);
  Real mu_top = clamp_cosine((r * mu + d) / top);
  Real beyond = chapman_optical_depth_to_infinity(R, scale_height, top, mu_top);
  if (mu >= Real(0.0)) {
    return chapman_optical_depth_to_infinity(R, scale_height, r, mu) - beyond;
  }
  Real r_p = r * sqrt(max(Real(1.0) - mu * mu, Real(0.0)));
  return Real(2.0) * chapman_optical_depth_to_infinity(R, scale_height, r_p, Real(0.0)) -
         chapman_optical_depth_to_infinity(R, scale_height, r, -mu) - beyond;
}

// --- Transmittance LUT parameterisation (Bruneton 2017, section 4) -----------
// x_r = rho / H with rho the distance to the horizon and H its value at the
// top; x_mu spreads the distance to the top between its extremes d_min and
// d_max.
Real2 transmittance_uv_from_r_mu(IN(Atmosphere) atmosphere, Real r, Real mu, Real2 size) {
  Real H = sqrt(atmosphere.top_radius * atmosphere.top_radius -
                atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real rho = safe_sqrt(r * r - atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real d = distance_to_top_boundary(atmosphere, r, mu);
  Real d_min = atmosphere.top_radius - r;
  Real d_max = rho + H;
  Real x_mu = (d - d_min) / (d_max - d_min);
  Real x_r = rho / H;
  return Real2(texture_coord_from_unit_range(x_mu, size.x),
               texture_coord_from_unit_range(x_r, size.y));
}

// The inverse: (r, mu) at texture coordinates uv. Returns (r, mu).
Real2 transmittance_r_mu_from_uv(IN(Atmosphere) atmosphere, Real2 uv, Real2 size) {
  Real x_mu = unit_range_from_texture_coord(uv.x, size.x);
  Real x_r = unit_range_from_texture_coord(uv.y, size.y);
  Real H = sqrt(atmosphere.top_radius * atmosphere.top_radius -
                atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real rho = H * x_r;
  Real r = sqrt(rho * rho + atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real d_min = atmosphere.top_radius - r;
  Real d_max = rho + H;
  Real d = d_min + x_mu * (d_max - d_min);
  // Law of cosines at the top: top^2 = r^2 + d^2 + 2 r d mu.
  Real mu = d == Real(0.0) ? Real(1.0) : (H * H - rho * rho - d * d) / (Real(2.0) * r * d);
  return Real2(r, clamp_cosine(mu));
}

// --- Transmittance LUT (Bruneton 2017, sec. 4.1) -----------------------------
// Bruneton's mapping above, held to the texel-centre
// range: a ray below the horizon or a point under the ground reads the
// LUT's edge, where the planet's shadow test takes over anyway.
void transmittance_lut_uv_from_r_mu(IN(Atmosphere) atmosphere, Real r, Real mu, OUT(Real) u,
                                    OUT(Real) v) {
  Real2 uv = transmittance_uv_from_r_mu(
      atmosphere, r, mu, Real2(Real(kTransmittanceLutWidth), Real(kTransmittanceLutHeight)));
  u = clamp(uv.x, texture_coord_from_unit_range(Real(0.0), Real(kTransmittanceLutWidth)),
            texture_coord_from_unit_range(Real(1.0), Real(kTransmittanceLutWidth)));
  v = clamp(uv.y, texture_coord_from_unit_range(Real(0.0), Real(kTransmittanceLutHeight)),
            texture_coord_from_unit_range(Real(1.0), Real(kTransmittanceLutHeight)));
}

void transmittance_lut_r_mu_from_uv(IN(Atmosphere) atmosphere, Real u, Real v, OUT(Real) r,
                                    OUT(Real) mu) {
  Real2 r_mu = transmittance_r_mu_from_uv(
      atmosphere, Real2(u, v), Real2(Real(kTransmittanceLutWidth), Real(kTransmittanceLutHeight)));
  r = r_mu.x;
  mu = r_mu.y;
}
