// The space-view LUT: the sky seen from outside the atmosphere's shell, in
// the camera's local frame (z up, x toward the sun's azimuth), where the
// per-pixel path would march every pixel whose ray crosses the shell. From
// a camera at radius r_c outside the shell, a ray is given by its
// azimuth phi from the sun's (the sky is the same at -phi) and by its
// distance p from the planet's centre, r_c sin(nadir angle): two numbers,
// as the sky-view LUT's two are inside. Two tables over (phi, p):
//  - open sky over the limb: the luminance of the whole ray through the
//    air (open sky that meets the ground is the slices' at altitude 0 and
//    the lit ground behind them);
//  - the air in front of a surface: a 3D table whose slices hold the
//    luminance and transmittance from where the ray enters the shell down
//    to an altitude h, on a grid of altitudes (space_view_slice_altitude)
//    over the ground's range of heights, where every surface lies. A ray
//    that does not come down to h (its closest approach is higher) holds
//    its values at the closest approach; rows whose rays all pass over the
//    highest ground (and whose neighbours' do) are never read, and left.
// Rows over p: the lower half for rays that meet the bottom sphere, by
// the angle acos(p / R_b) (linear in p at the nadir, in the half chord
// sqrt(R_b^2 - p^2) at the horizon: the half chord alone left the nadir's
// first row 925 km out on Earth, and pixels at the terminator seen from
// 40 000 km up to 2.3 times the march's), the upper half for rays that pass over it, by
// sqrt(p^2 - R_b^2) (Bruneton 2017's rho), which crowds them toward the
// dense air at the limb. Columns are even over phi: crowded toward the
// sun's azimuth (phi = pi u^2, as the sky-view LUT's), they left the far
// side of a twilight limb from 3000 km 1.1 % off the march, against 0.8.

// The texture coordinate v of a ray at distance p from the centre, kept
// within its half so that the two halves (the ground and the limb just
// above it) never blend.
float space_view_v_from_p(Atmosphere atmosphere, float p) {
  float rb = atmosphere.bottom_radius;
  float half_rows = float(kSpaceViewLutHeight / 2);
  float x;
  if (p < rb) {
    float a = acos(clamp(p / rb, 0.0, 1.0)) / (0.5 * kPi);  // 1 at the nadir, 0 at the horizon
    x = clamp((1.0 - a) * (half_rows - 1.0), 0.0, half_rows - 1.0);
  } else {
    float rho_top = safe_sqrt(atmosphere.top_radius * atmosphere.top_radius - rb * rb);
    float rho = safe_sqrt(p * p - rb * rb) / rho_top;
    x = half_rows + clamp(rho * (half_rows - 1.0), 0.0, half_rows - 1.0);
  }
  return (x + 0.5) / float(kSpaceViewLutHeight);
}

// The distance from the centre of row j's rays.
float space_view_p_from_row(Atmosphere atmosphere, int j) {
  float rb = atmosphere.bottom_radius;
  int half_rows = kSpaceViewLutHeight / 2;
  if (j < half_rows) {
    float a = 1.0 - float(j) / float(half_rows - 1);
    return rb * cos(0.5 * kPi * a);
  }
  float rho_top = safe_sqrt(atmosphere.top_radius * atmosphere.top_radius - rb * rb);
  float rho = rho_top * float(j - half_rows) / float(half_rows - 1);
  return sqrt(rb * rb + rho * rho);
}

// The texture coordinate u of azimuth phi (texel centres at 0 and pi).
float space_view_u_from_phi(float phi) {
  return texture_coord_from_unit_range(clamp(phi / kPi, 0.0, 1.0), float(kSpaceViewLutWidth));
}

float space_view_phi_from_column(int i) {
  float u = float(i) / float(kSpaceViewLutWidth - 1);
  return kPi * u;
}

// Slice k's altitude, evenly over the ground's heights `ground` (lowest,
// highest: metres above the bottom sphere; a smooth body's get a metre).
float space_view_slice_altitude(vec2 ground, int k) {
  float lo = ground.x, hi = max(ground.y, ground.x + 1.0);
  return lo + (hi - lo) * float(k) / float(kSpaceViewLutDepth - 1);
}

// The texture coordinate w of altitude h, the inverse of the above.
float space_view_w_from_altitude(vec2 ground, float h) {
  float lo = ground.x, hi = max(ground.y, ground.x + 1.0);
  return texture_coord_from_unit_range(clamp((h - lo) / (hi - lo), 0.0, 1.0),
                                       float(kSpaceViewLutDepth));
}
