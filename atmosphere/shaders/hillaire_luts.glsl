// Hillaire 2020's LUTs: how each maps its texels to the quantities it
// holds, and back (the common subset of GLSL and C++: see definitions.glsl;
// the sizes are in lut_sizes.glsl). Included before hillaire_functions.glsl.

// --- Multiple-scattering LUT (Hillaire 2020, sec. 5.5) ------------------------
// Psi_ms depends on altitude and sun zenith only: y = altitude / thickness
// and x = sky_irradiance_u_from_mu_s(mu_s), both texel-centred. The paper
// maps mu_s linearly; the square root packs texels around the terminator,
// where the light at a point changes fastest: with 32 linear texels the
// twilight sky's higher orders moved by half between 32 and 128 texels.
void multiple_scattering_lut_uv_from_r_mu_s(IN(Atmosphere) atmosphere, Real r, Real mu_s,
                                            OUT(Real) u, OUT(Real) v) {
  Real x_r = (r - atmosphere.bottom_radius) / (atmosphere.top_radius - atmosphere.bottom_radius);
  u = texture_coord_from_unit_range(sky_irradiance_u_from_mu_s(mu_s), Real(kMultipleScatteringLutWidth));
  v = texture_coord_from_unit_range(clamp(x_r, Real(0.0), Real(1.0)), Real(kMultipleScatteringLutHeight));
}

void multiple_scattering_lut_r_mu_s_from_uv(IN(Atmosphere) atmosphere, Real u, Real v,
                                            OUT(Real) r, OUT(Real) mu_s) {
  Real x_mu_s = clamp(unit_range_from_texture_coord(u, Real(kMultipleScatteringLutWidth)), Real(0.0), Real(1.0));
  Real x_r = clamp(unit_range_from_texture_coord(v, Real(kMultipleScatteringLutHeight)), Real(0.0), Real(1.0));
  mu_s = mu_s_from_sky_irradiance_u(x_mu_s);
  r = atmosphere.bottom_radius + x_r * (atmosphere.top_radius - atmosphere.bottom_radius);
}

// Order n of scattering (from 1) is held on a grid of this many texels over
// the same mapping: the LUT's own for the first kFineScatteringOrders, a
// coarser one for the rest.
int scattering_order_width(int order) {
  return order <= kFineScatteringOrders ? kMultipleScatteringLutWidth : kCoarseOrderWidth;
}
int scattering_order_height(int order) {
  return order <= kFineScatteringOrders ? kMultipleScatteringLutHeight : kCoarseOrderHeight;
}

// A texture coordinate on a grid of `from` texels to the coordinate of the
// same point on a grid of `to` texels over the same range (both
// texel-centred).
Real regrid_texture_coord(Real u, int from, int to) {
  return texture_coord_from_unit_range(unit_range_from_texture_coord(u, Real(from)), Real(to));
}

// The ground-irradiance table: one row over mu_s, the same mapping.
Real ground_irradiance_lut_u_from_mu_s(Real mu_s) {
  return texture_coord_from_unit_range(sky_irradiance_u_from_mu_s(mu_s), Real(kMultipleScatteringLutWidth));
}

// --- Sky-view LUT (Hillaire 2020, sec. 5.3, extended to the full azimuth) ----
// The view zenith angle of the true horizon seen from r is pi - beta with
// cos(beta) = sqrt(r^2 - R^2) / r. The upper half of the texture holds the
// sky, the lower half the ground, each with a square law that packs texels
// at the horizon (v = 1/2), where the sky changes fastest. Azimuth phi is
// measured from the sun's azimuth over the full circle (-pi, pi], with a
// square law that packs texels toward the sun for the Mie peak; the
// texture wraps in u, so that no seam shows behind the viewer and a second
// light can use the same table.
Real sky_view_horizon_zenith(IN(Atmosphere) atmosphere, Real r) {
  Real cos_beta = safe_sqrt(r * r - atmosphere.bottom_radius * atmosphere.bottom_radius) / r;
  return kPi - acos(clamp(cos_beta, Real(0.0), Real(1.0)));
}

void sky_view_lut_uv_from_view(IN(Atmosphere) atmosphere, Real r, Real mu, Real phi, OUT(Real) u,
                               OUT(Real) v) {
  Real theta_h = sky_view_horizon_zenith(atmosphere, r);
  Real theta = acos(clamp_cosine(mu));
  if (theta < theta_h) {
    v = Real(0.5) - Real(0.5) * safe_sqrt(Real(1.0) - theta / theta_h);
  } else {
    Real beta = kPi - theta_h;
    v = Real(0.5) + Real(0.5) * safe_sqrt((theta - theta_h) / max(beta, Real(1e-6)));
  }
  Real s = sign(phi) * safe_sqrt(abs(phi) / kPi);
  u = Real(0.5) + Real(0.5) * s;
}

void sky_view_lut_view_from_uv(IN(Atmosphere) atmosphere, Real r, Real u, Real v, OUT(Real) mu,
                               OUT(Real) phi) {
  Real theta_h = sky_view_horizon_zenith(atmosphere, r);
  Real theta;
  if (v < Real(0.5)) {
    Real a = Real(1.0) - Real(2.0) * v;
    theta = theta_h * (Real(1.0) - a * a);
  } else {
    Real a = Real(2.0) * v - Real(1.0);
    theta = theta_h + (kPi - theta_h) * a * a;
  }
  mu = cos(theta);
  Real s = Real(2.0) * u - Real(1.0);
  phi = kPi * s * abs(s);
}

// --- Aerial-perspective froxels (Hillaire 2020, sec. 5.4) ---------------------
// Slice k's centre lies at distance range * ((k + 1/2) / N)^2 along the
// pixel's ray: slices are thin near the camera, where the eye sees detail.
Real aerial_slice_distance(Real range, Real w) { return range * w * w; }
Real aerial_slice_coord(Real range, Real t) { return sqrt(max(t, Real(0.0)) / range); }

// --- Forward-gain LUT (hillaire_functions.glsl, "The sun's glow") ------------
// The LUT's mapping: u = sin(theta / 2) (theta the angle from the sun),
// which keeps texels where the peak is; v = tau / (tau + 2), which covers
// every depth, fine where the gain grows fastest. Both texel-centred.
void forward_gain_lut_uv_from_nu_tau(Real nu, Real tau, OUT(Real) u, OUT(Real) v) {
  u = texture_coord_from_unit_range(safe_sqrt(Real(0.5) * (Real(1.0) - nu)), Real(kForwardGainLutWidth));
  Real t = max(tau, Real(0.0));
  v = texture_coord_from_unit_range(t / (t + Real(2.0)), Real(kForwardGainLutHeight));
}

void forward_gain_lut_nu_tau_from_uv(Real u, Real v, OUT(Real) nu, OUT(Real) tau) {
  Real s = unit_range_from_texture_coord(u, Real(kForwardGainLutWidth));
  nu = Real(1.0) - Real(2.0) * s * s;
  Real w = min(unit_range_from_texture_coord(v, Real(kForwardGainLutHeight)), Real(1.0) - Real(1e-6));
  tau = Real(2.0) * w / (Real(1.0) - w);
}
