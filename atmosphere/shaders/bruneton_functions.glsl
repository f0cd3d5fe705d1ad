// Bruneton and Neyret 2008, "Precomputed Atmospheric Scattering", as Bruneton
// reworked it in 2017: transmittance (2D), single and multiple scattering in
// 4D over (r, mu, mu_s, nu) packed in a 3D texture, and the ground's
// irradiance (2D), each order of scattering from the one before. In the
// common subset of GLSL and C++-with-GLM (see definitions.glsl): the passes
// of atmosphere/gpu/bruneton compile this same file after the shared math
// (bruneton_common.glsl), and so does, as C++ in double, the test that
// checks the tables' parameterisations against the GPU's
// (tests/atmosphere/bruneton_functions_gl_test.cpp); no CPU code reads the
// tables, so the functions that sample them are tested on the technique's
// images (tests/atmosphere/bruneton_gl_test.cpp) alone.
//
// The including side defines Real4 and the texture types Table2D and
// Table3D (sampler2D and sampler3D on the GPU) with texture(table, uv)
// sampling them linearly with clamped edges, before this file; and, after
// it, bruneton_sizes() (declared below): the tables' sizes, a quality of the
// technique, and the smallest sun zenith cosine the tables cover.

struct BrunetonSizes {
  int transmittance_width, transmittance_height;
  int irradiance_width, irradiance_height;
  int r, mu, mu_s, nu;  // the 4D scattering table; texels (nu mu_s) x mu x r
  Real mu_s_min;
};

BrunetonSizes bruneton_sizes();

// --- Transmittance (Bruneton 2017, sec. "Transmittance") ---------------------
Real2 bruneton_transmittance_size() {
  BrunetonSizes s = bruneton_sizes();
  return Real2(Real(s.transmittance_width), Real(s.transmittance_height));
}

// The table holds the optical depth to the top, not its exponential
// (ours; Bruneton stores the transmittance). Between two points of a ray
// Bruneton divides two transmittances to the top: along the horizon of a
// dense atmosphere (50x Earth's air: some 900 in blue) both are 0 in
// 32-bit floats, their ratio is 0 / 0, and the horizon's texels of every
// order summed light over hundreds of kilometres unattenuated, up to
// 1000x the ground truth. The difference of two optical depths has no such
// edge, and bilinear filtering of a depth is closer to exact than of its
// exponential.
//
// To the top along (r, mu), for a ray that does not meet the ground; one
// bilinear lookup of the shared mapping (transmittance.glsl).
Real3 bruneton_optical_depth_to_top(IN(Atmosphere) atmosphere, IN(Table2D) table, Real r,
                                    Real mu) {
  Real2 uv = transmittance_uv_from_r_mu(atmosphere, r, mu, bruneton_transmittance_size());
  return Real3(texture(table, uv));
}

Real3 bruneton_transmittance_to_top(IN(Atmosphere) atmosphere, IN(Table2D) table, Real r,
                                    Real mu) {
  return exp(-bruneton_optical_depth_to_top(atmosphere, table, r, mu));
}

// Between the point at distance d along (r, mu) and r itself: the
// difference of two depths to the top, taken along -mu where the ray meets
// the ground (its rays to the top would run through the planet). `from_r`
// is the depth at r itself (bruneton_optical_depth_from), the same for
// every d of a ray.
Real3 bruneton_optical_depth_from(IN(Atmosphere) atmosphere, IN(Table2D) table, Real r, Real mu,
                                  bool ray_r_mu_intersects_ground) {
  return bruneton_optical_depth_to_top(atmosphere, table, r, ray_r_mu_intersects_ground ? -mu : mu);
}

// The depth between r and the point at distance d. One lookup: a ternary
// between two lookups would cost both on llvmpipe, which runs every side
// of a branch.
Real3 bruneton_optical_depth_along(IN(Atmosphere) atmosphere, IN(Table2D) table, IN(Real3) from_r,
                                   Real r, Real mu, Real d, bool ray_r_mu_intersects_ground) {
  Real r_d = clamp(sqrt(d * d + Real(2.0) * r * mu * d + r * r), atmosphere.bottom_radius,
                   atmosphere.top_radius);
  Real mu_d = clamp_cosine((r * mu + d) / r_d);
  Real3 at_d =
      bruneton_optical_depth_to_top(atmosphere, table, r_d, ray_r_mu_intersects_ground ? -mu_d : mu_d);
  return max(ray_r_mu_intersects_ground ? at_d - from_r : from_r - at_d, Real3(0.0));
}

Real3 bruneton_transmittance_along(IN(Atmosphere) atmosphere, IN(Table2D) table, IN(Real3) from_r,
                                   Real r, Real mu, Real d, bool ray_r_mu_intersects_ground) {
  return exp(-bruneton_optical_depth_along(atmosphere, table, from_r, r, mu, d,
                                           ray_r_mu_intersects_ground));
}

Real3 bruneton_transmittance(IN(Atmosphere) atmosphere, IN(Table2D) table, Real r, Real mu, Real d,
                             bool ray_r_mu_intersects_ground) {
  return bruneton_transmittance_along(
      atmosphere, table,
      bruneton_optical_depth_from(atmosphere, table, r, mu, ray_r_mu_intersects_ground), r, mu, d,
      ray_r_mu_intersects_ground);
}

// The sun's light at r: the transmittance times the part of the sun's disk
// above the horizon, which rises like a smoothstep over the disk's angular
// size as mu_s crosses the horizon's cosine.
Real3 bruneton_transmittance_to_sun(IN(Atmosphere) atmosphere, IN(Table2D) table, Real r,
                                    Real mu_s) {
  Real sin_theta_h = atmosphere.bottom_radius / r;
  Real cos_theta_h = -safe_sqrt(Real(1.0) - sin_theta_h * sin_theta_h);
  Real alpha = atmosphere.sun_angular_radius;
  return bruneton_transmittance_to_top(atmosphere, table, r, mu_s) *
         smoothstep(-sin_theta_h * alpha, sin_theta_h * alpha, mu_s - cos_theta_h);
}

// The nearest boundary along (r, mu): the ground or the top.
Real bruneton_distance_to_boundary(IN(Atmosphere) atmosphere, Real r, Real mu,
                                   bool ray_r_mu_intersects_ground) {
  return ray_r_mu_intersects_ground ? distance_to_bottom_boundary(atmosphere, r, mu)
                                    : distance_to_top_boundary(atmosphere, r, mu);
}

// --- The 4D scattering table's parameterisation (Bruneton 2017) --------------
// mu_s -> [0, 1] and back: Bruneton's map of the distance to the top for a
// sun ray from the ground, 0 at mu_s_min and 1 at the zenith, which packs
// texels at the horizon. (Blending it with a map uniform in the sun's
// zenith angle, which gives a high sun more texels, was tried: half and
// half left Earth noon as good as doubling the texels and twilight 4 times
// worse, 48 % against 11 %.)
Real bruneton_unit_from_mu_s(IN(Atmosphere) atmosphere, Real mu_s) {
  BrunetonSizes s = bruneton_sizes();
  Real bottom = atmosphere.bottom_radius, top = atmosphere.top_radius;
  Real H = sqrt(top * top - bottom * bottom);
  Real d = distance_to_top_boundary(atmosphere, bottom, mu_s);
  Real d_min = top - bottom;
  Real d_max = H;
  Real a = (d - d_min) / (d_max - d_min);
  Real D = distance_to_top_boundary(atmosphere, bottom, s.mu_s_min);
  Real A = (D - d_min) / (d_max - d_min);
  return max(Real(1.0) - a / A, Real(0.0)) / (Real(1.0) + a);
}

Real bruneton_mu_s_from_unit(IN(Atmosphere) atmosphere, Real x_mu_s) {
  BrunetonSizes s = bruneton_sizes();
  Real bottom = atmosphere.bottom_radius, top = atmosphere.top_radius;
  Real H = sqrt(top * top - bottom * bottom);
  Real d_min = top - bottom;
  Real d_max = H;
  Real D = distance_to_top_boundary(atmosphere, bottom, s.mu_s_min);
  Real A = (D - d_min) / (d_max - d_min);
  Real a = (A - x_mu_s * A) / (Real(1.0) + x_mu_s * A);
  Real d = d_min + min(a, A) * (d_max - d_min);
  return d == Real(0.0) ? Real(1.0) : clamp_cosine((H * H - d * d) / (Real(2.0) * bottom * d));
}

// r by the distance to the horizon; mu by the distance to the boundary the
// ray meets, the lower half of the texture for rays that meet the ground and
// the upper half for those that do not, so that the horizon falls between
// texels; mu_s by the distance to the top for a sun ray from the ground,
// through an ad-hoc map that is 0 at mu_s_min and packs texels at the
// horizon; nu linearly.
Real4 bruneton_uvwz_from_r_mu_mu_s_nu(IN(Atmosphere) atmosphere, Real r, Real mu, Real mu_s,
                                      Real nu, bool ray_r_mu_intersects_ground) {
  BrunetonSizes s = bruneton_sizes();
  Real bottom = atmosphere.bottom_radius, top = atmosphere.top_radius;
  Real H = sqrt(top * top - bottom * bottom);
  Real rho = safe_sqrt(r * r - bottom * bottom);
  Real u_r = texture_coord_from_unit_range(rho / H, Real(s.r));
  Real r_mu = r * mu;
  Real discriminant = r_mu * r_mu - r * r + bottom * bottom;
  Real u_mu;
  if (ray_r_mu_intersects_ground) {
    Real d = -r_mu - safe_sqrt(discriminant);
    Real d_min = r - bottom;
    Real d_max = rho;
    u_mu = Real(0.5) - Real(0.5) * texture_coord_from_unit_range(
                                       d_max == d_min ? Real(0.0) : (d - d_min) / (d_max - d_min),
                                       Real(s.mu / 2));
  } else {
    Real d = -r_mu + safe_sqrt(discriminant + H * H);
    Real d_min = top - r;
    Real d_max = rho + H;
    u_mu = Real(0.5) +
           Real(0.5) * texture_coord_from_unit_range((d - d_min) / (d_max - d_min), Real(s.mu / 2));
  }
  Real u_mu_s = texture_coord_from_unit_range(bruneton_unit_from_mu_s(atmosphere, mu_s), Real(s.mu_s));
  Real u_nu = (nu + Real(1.0)) / Real(2.0);
  return Real4(u_nu, u_mu_s, u_mu, u_r);
}

// The inverse, from unit coordinates.
void bruneton_r_mu_mu_s_nu_from_uvwz(IN(Atmosphere) atmosphere, IN(Real4) uvwz, OUT(Real) r,
                                     OUT(Real) mu, OUT(Real) mu_s, OUT(Real) nu,
                                     OUT(bool) ray_r_mu_intersects_ground) {
  BrunetonSizes s = bruneton_sizes();
  Real bottom = atmosphere.bottom_radius, top = atmosphere.top_radius;
  Real H = sqrt(top * top - bottom * bottom);
  Real rho = H * unit_range_from_texture_coord(uvwz.w, Real(s.r));
  r = sqrt(rho * rho + bottom * bottom);
  if (uvwz.z < Real(0.5)) {
    Real d_min = r - bottom;
    Real d_max = rho;
    Real d = d_min + (d_max - d_min) * unit_range_from_texture_coord(Real(1.0) - Real(2.0) * uvwz.z,
                                                                     Real(s.mu / 2));
    mu = d == Real(0.0) ? Real(-1.0) : clamp_cosine(-(rho * rho + d * d) / (Real(2.0) * r * d));
    ray_r_mu_intersects_ground = true;
  } else {
    Real d_min = top - r;
    Real d_max = rho + H;
    Real d = d_min + (d_max - d_min) * unit_range_from_texture_coord(Real(2.0) * uvwz.z - Real(1.0),
                                                                     Real(s.mu / 2));
    mu = d == Real(0.0) ? Real(1.0)
                        : clamp_cosine((H * H - rho * rho - d * d) / (Real(2.0) * r * d));
    ray_r_mu_intersects_ground = false;
  }
  mu_s = bruneton_mu_s_from_unit(atmosphere, unit_range_from_texture_coord(uvwz.y, Real(s.mu_s)));
  nu = clamp_cosine(uvwz.x * Real(2.0) - Real(1.0));
}

// The texel (x, y, z) of the 3D texture, x = nu * mu_s_size + mu_s: its
// parameters, with nu held to the range that mu and mu_s allow.
void bruneton_r_mu_mu_s_nu_from_texel(IN(Atmosphere) atmosphere, IN(Real3) texel, OUT(Real) r,
                                      OUT(Real) mu, OUT(Real) mu_s, OUT(Real) nu,
                                      OUT(bool) ray_r_mu_intersects_ground) {
  BrunetonSizes s = bruneton_sizes();
  Real texel_nu = floor(texel.x / Real(s.mu_s));
  Real texel_mu_s = texel.x - texel_nu * Real(s.mu_s);
  // The nu axis is not texel-centred: its extremes are its first and last
  // columns of mu_s slices, which GetScattering interpolates between.
  Real4 uvwz = Real4(texel_nu / Real(s.nu - 1), (texel_mu_s + Real(0.5)) / Real(s.mu_s),
                     (texel.y + Real(0.5)) / Real(s.mu), (texel.z + Real(0.5)) / Real(s.r));
  bruneton_r_mu_mu_s_nu_from_uvwz(atmosphere, uvwz, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  Real spread = safe_sqrt((Real(1.0) - mu * mu) * (Real(1.0) - mu_s * mu_s));
  nu = clamp(nu, mu * mu_s - spread, mu * mu_s + spread);
}

// A 4D table at (r, mu, mu_s, nu): two lookups of the 3D texture, at the nu
// slices on either side, interpolated.
Real4 bruneton_scattering_lookup(IN(Atmosphere) atmosphere, IN(Table3D) table, Real r, Real mu,
                                 Real mu_s, Real nu, bool ray_r_mu_intersects_ground) {
  BrunetonSizes s = bruneton_sizes();
  Real4 uvwz =
      bruneton_uvwz_from_r_mu_mu_s_nu(atmosphere, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  Real tex_coord_x = uvwz.x * Real(s.nu - 1);
  Real tex_x = floor(tex_coord_x);
  Real lerp = tex_coord_x - tex_x;
  Real3 uvw0 = Real3((tex_x + uvwz.y) / Real(s.nu), uvwz.z, uvwz.w);
  Real3 uvw1 = Real3((tex_x + Real(1.0) + uvwz.y) / Real(s.nu), uvwz.z, uvwz.w);
  return texture(table, uvw0) * (Real(1.0) - lerp) + texture(table, uvw1) * lerp;
}

// --- The ground's irradiance table: mu_s (u) by altitude (v), linear ---------
Real2 bruneton_irradiance_uv_from_r_mu_s(IN(Atmosphere) atmosphere, Real r, Real mu_s) {
  BrunetonSizes s = bruneton_sizes();
  Real x_r = (r - atmosphere.bottom_radius) / (atmosphere.top_radius - atmosphere.bottom_radius);
  Real x_mu_s = mu_s * Real(0.5) + Real(0.5);
  return Real2(texture_coord_from_unit_range(x_mu_s, Real(s.irradiance_width)),
               texture_coord_from_unit_range(x_r, Real(s.irradiance_height)));
}

void bruneton_r_mu_s_from_irradiance_uv(IN(Atmosphere) atmosphere, IN(Real2) uv, OUT(Real) r,
                                        OUT(Real) mu_s) {
  BrunetonSizes s = bruneton_sizes();
  Real x_mu_s = unit_range_from_texture_coord(uv.x, Real(s.irradiance_width));
  Real x_r = unit_range_from_texture_coord(uv.y, Real(s.irradiance_height));
  r = atmosphere.bottom_radius + x_r * (atmosphere.top_radius - atmosphere.bottom_radius);
  mu_s = clamp_cosine(Real(2.0) * x_mu_s - Real(1.0));
}

Real3 bruneton_irradiance(IN(Atmosphere) atmosphere, IN(Table2D) table, Real r, Real mu_s) {
  return Real3(texture(table, bruneton_irradiance_uv_from_r_mu_s(atmosphere, r, mu_s)));
}

// --- Samples along a ray --------------------------------------------------
// Bruneton integrates single and multiple scattering by the trapezoid rule
// over `steps` equal intervals to the boundary. The air's density falls
// off exponentially from the ground (Mie's over 1.2 km on Earth) and an
// upward ray runs some 100 km: the rule's samples are kilometres apart
// where the density changes most, and at Earth noon the sky's single Mie
// came out 7 % bright near the sun with 50 of them (a convex integrand,
// which the trapezoid overestimates). Here the samples sit at equal steps of
// a variable s in [0, 1] mapped onto the ray by two square laws that crowd
// the samples toward the ray's point nearest the planet's centre, where
// the air is densest (the camera for an upward ray, the ground for a
// downward one, the tangent point for a ray past the limb); with the same
// 50 samples single scattering matches the path tracer's first order to
// 0.1 %. Sample i of steps: its distance.
//
// Between two samples the transmittance to the camera is integrated as the
// exponential it is, not by the trapezoid (ours; Bruneton uses the rule for
// both factors). In a dense atmosphere the light's free path is shorter
// than the samples' spacing: the trapezoid then gives the first interval's
// scattering all of half its length, each order came out brighter than the
// one before it, and 10 orders of the 50x dense Earth summed to 1500x the
// ground truth in blue. Exact, an interval's weight never passes the free
// path, and in thin air it is the trapezoid's.
Real bruneton_ray_sample(Real r, Real mu, Real length, int i, int steps) {
  Real t_c = clamp(-r * mu, Real(0.0), length);
  Real s_c = length > Real(0.0) ? t_c / length : Real(0.0);
  Real s = Real(i) / Real(steps);
  if (s < s_c) {
    Real a = Real(1.0) - s / s_c;
    return t_c - t_c * a * a;
  }
  Real a = s_c < Real(1.0) ? (s - s_c) / (Real(1.0) - s_c) : Real(0.0);
  return t_c + (length - t_c) * a * a;
}

// Half the integral of the camera's transmittance over an interval of
// length dt whose ends see transmittances a and b, at optical depths
// depth_a and depth_b from the camera (exponential between them): what the
// sum of the integrand's other factor at the two ends is multiplied by.
Real3 bruneton_segment_weight(Real3 a, Real3 b, Real3 depth_a, Real3 depth_b, Real dt) {
  Real3 w;
  for (int c = 0; c < 3; ++c) {
    Real optical = depth_b[c] - depth_a[c];
    // (a - b) / optical, and the trapezoid's mean where the air is thin.
    w[c] = optical > Real(1e-4) ? (a[c] - b[c]) / optical : Real(0.5) * (a[c] + b[c]);
  }
  return Real(0.5) * dt * w;
}

// --- Single scattering (Bruneton 2017, "Single scattering") -----------------
// Rayleigh and Mie scattered once toward the camera along (r, mu), without
// their phase functions (applied when the table is read: nu is known then),
// in units of the solar irradiance, over `steps` samples to the nearest
// boundary (bruneton_ray_sample).
void bruneton_single_scattering(IN(Atmosphere) atmosphere, IN(Table2D) transmittance, Real r,
                                Real mu, Real mu_s, Real nu, bool ray_r_mu_intersects_ground,
                                int steps, OUT(Real3) rayleigh, OUT(Real3) mie) {
  Real length = bruneton_distance_to_boundary(atmosphere, r, mu, ray_r_mu_intersects_ground);
  Real3 from_r =
      bruneton_optical_depth_from(atmosphere, transmittance, r, mu, ray_r_mu_intersects_ground);
  Real3 rayleigh_sum = Real3(0.0), mie_sum = Real3(0.0);
  Real d_before = Real(0.0);
  Real3 view_before = Real3(1.0), depth_before = Real3(0.0);
  Real3 rayleigh_before = Real3(0.0), mie_before = Real3(0.0);
  for (int i = 0; i <= steps; ++i) {
    Real d = bruneton_ray_sample(r, mu, length, i, steps);
    Real r_d = clamp(sqrt(d * d + Real(2.0) * r * mu * d + r * r), atmosphere.bottom_radius,
                     atmosphere.top_radius);
    Real mu_s_d = clamp_cosine((r * mu_s + d * nu) / r_d);
    Real3 depth = bruneton_optical_depth_along(atmosphere, transmittance, from_r, r, mu, d,
                                               ray_r_mu_intersects_ground);
    Real3 view = exp(-depth);
    Real3 sun = bruneton_transmittance_to_sun(atmosphere, transmittance, r_d, mu_s_d);
    Real altitude = r_d - atmosphere.bottom_radius;
    Real3 rayleigh_here = sun * profile_density(atmosphere.rayleigh_density, altitude);
    Real3 mie_here = sun * profile_density(atmosphere.mie_density, altitude);
    if (i > 0) {
      Real3 w = bruneton_segment_weight(view_before, view, depth_before, depth, d - d_before);
      rayleigh_sum += w * (rayleigh_before + rayleigh_here);
      mie_sum += w * (mie_before + mie_here);
    }
    d_before = d;
    view_before = view;
    depth_before = depth;
    rayleigh_before = rayleigh_here;
    mie_before = mie_here;
  }
  rayleigh = rayleigh_sum * atmosphere.solar_irradiance * atmosphere.rayleigh_scattering;
  mie = mie_sum * atmosphere.solar_irradiance * atmosphere.mie_scattering;
}

// --- Multiple scattering (Bruneton 2017, "Multiple scattering") -------------
// The radiance of one more order arriving along (r, mu): the scattering
// density (the light of the order before scattered once, a 4D table) times
// the transmittance, integrated to the nearest boundary over the samples of
// bruneton_ray_sample.
Real3 bruneton_multiple_scattering(IN(Atmosphere) atmosphere, IN(Table2D) transmittance,
                                   IN(Table3D) density, Real r, Real mu, Real mu_s, Real nu,
                                   bool ray_r_mu_intersects_ground, int steps) {
  Real length = bruneton_distance_to_boundary(atmosphere, r, mu, ray_r_mu_intersects_ground);
  Real3 from_r =
      bruneton_optical_depth_from(atmosphere, transmittance, r, mu, ray_r_mu_intersects_ground);
  Real3 sum = Real3(0.0);
  Real d_before = Real(0.0);
  Real3 view_before = Real3(1.0), depth_before = Real3(0.0), j_before = Real3(0.0);
  for (int i = 0; i <= steps; ++i) {
    Real d = bruneton_ray_sample(r, mu, length, i, steps);
    Real r_i = clamp(sqrt(d * d + Real(2.0) * r * mu * d + r * r), atmosphere.bottom_radius,
                     atmosphere.top_radius);
    Real mu_i = clamp_cosine((r * mu + d) / r_i);
    Real mu_s_i = clamp_cosine((r * mu_s + d * nu) / r_i);
    Real3 j = Real3(bruneton_scattering_lookup(atmosphere, density, r_i, mu_i, mu_s_i, nu,
                                               ray_r_mu_intersects_ground));
    Real3 depth = bruneton_optical_depth_along(atmosphere, transmittance, from_r, r, mu, d,
                                               ray_r_mu_intersects_ground);
    Real3 view = exp(-depth);
    if (i > 0) {
      sum += bruneton_segment_weight(view_before, view, depth_before, depth, d - d_before) *
             (j_before + j);
    }
    d_before = d;
    view_before = view;
    depth_before = depth;
    j_before = j;
  }
  return sum;
}

// --- The ground's irradiance (Bruneton 2017, "Ground irradiance") -----------
// From the sun, over the visible part of its disk (the cosine factor
// averaged over it).
Real3 bruneton_direct_irradiance(IN(Atmosphere) atmosphere, IN(Table2D) transmittance, Real r,
                                 Real mu_s) {
  Real alpha = atmosphere.sun_angular_radius;
  Real cosine = mu_s < -alpha ? Real(0.0)
                              : (mu_s > alpha ? mu_s : (mu_s + alpha) * (mu_s + alpha) / (Real(4.0) * alpha));
  return atmosphere.solar_irradiance *
         bruneton_transmittance_to_top(atmosphere, transmittance, r, mu_s) * cosine;
}
