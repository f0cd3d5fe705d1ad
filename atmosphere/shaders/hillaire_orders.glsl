// Hillaire 2020's multiple-scattering LUT texel by texel: the paper's
// Psi_ms, and the orders of scattering summed one by one (the common subset
// of GLSL and C++: see definitions.glsl). Included after
// hillaire_functions.glsl, whose integrals it gathers.

// --- Multiple-scattering LUT texel (Hillaire 2020, sec. 5.5, eqs. 5-10) ------
// The paper's form, kept for comparison (technique "hillaire2020"). At
// radius r with the sun at zenith cosine mu_s: the second-order luminance
// L_2 and the transfer f_ms, each averaged over the sphere of directions
// (the isotropic phase times the 4 pi solid angle), then
// Psi_ms = L_2 / (1 - f_ms), the sum of the geometric series of all orders
// (eq. 9). Per unit solar irradiance. The ground reflects the sun with its
// albedo.
//
// The direction at zenith cosine cos_theta in column i of n, whose azimuths
// phi are stratified uniformly.
Real3 gather_direction(Real cos_theta, int i, int n) {
  Real phi = Real(2.0) * kPi * (Real(i) + Real(0.5)) / Real(n);
  Real sin_theta = safe_sqrt(Real(1.0) - cos_theta * cos_theta);
  return Real3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

Real3 multiple_scattering_texel(IN(Atmosphere) atmosphere, Real r, Real mu_s) {
  Real3 o = Real3(0.0, 0.0, r);
  Real3 sun_dir = Real3(safe_sqrt(Real(1.0) - mu_s * mu_s), Real(0.0), mu_s);
  Real3 l_2 = Real3(0.0);
  Real3 f_ms = Real3(0.0);
  const int n = kMultipleScatteringDirectionsSqrt;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      // The paper's rows: cos(theta) stratified uniformly over the sphere.
      Real3 d = gather_direction(Real(1.0) - Real(2.0) * (Real(j) + Real(0.5)) / Real(n), i, n);
      Real t_end;
      bool hits_ground;
      ray_extent_inside(atmosphere, o, d, t_end, hits_ground);
      Real3 luminance, transmittance, f;
      integrate_scattering(atmosphere, o, d, Real(0.0), t_end, sun_dir, kMultipleScatteringSteps,
                           kSourceIsotropicSun, hits_ground, luminance, transmittance, f);
      l_2 += luminance;
      f_ms += f;
    }
  }
  Real inv_count = Real(1.0) / Real(n * n);
  l_2 *= inv_count;
  f_ms *= inv_count;
  return l_2 / (Real3(1.0) - f_ms);
}

// --- Scattering orders (the default multiple-scattering LUT) ------------------
// The paper's 1 / (1 - f_ms) assumes that every order sees the same
// neighbourhood as the second, and its L_2 leaves out the sky's light
// reflected by the ground. Against the path tracer (Earth, sun 60 deg up)
// the orders above the second come out 40 % low and the blue sky 7 %.
// Here the orders are summed one by one, each from the last, as
// Bruneton and Neyret do, but kept to Hillaire's 2D table over (r, mu_s):
// the light of an order at a point is described by its spherical-harmonic
// terms to degree kFieldDegree in the frame of the zenith and the sun
// (FieldMoments; Hillaire's isotropic assumption keeps the mean J_n alone,
// the higher terms carry the forward scattering of thick dust).
//   order 1: the sun scattered once (true phase functions) or reflected by
//        the ground, over the sphere at (r, mu_s);
//   E_1: the sun scattered once, as irradiance on the ground;
//   order n + 1: order n scattered once more (scattered_field) along
//        every direction, plus the ground lit by E_n; E_(n+1): order n
//        scattered onto the ground.
// Psi_ms = J_1 + ... + J_N plus the geometric tail J_N q / (1 - q), with q
// the ratio of the last two orders, and the other terms alike; the
// ground's sky light is the same sum over E_n (terrain and the 400 km view
// use it). N = kScatteringOrders.

// Row j of n over the sphere for a point at radius r: half the rows above
// the horizon, half below it, each packed toward the horizon by a square
// law, where the light arriving near the ground changes fastest (the sky
// brightens to the horizon, the ground begins). With uniform rows in
// cos(theta), 8 x 8 directions left the noon sky's higher orders 3 %
// lower than 16 x 16 did. Returns cos(theta) of the row's middle and sets
// `weight` to the row's share of the sphere (the rows' shares sum to 1).
// For the ground's hemisphere (`upper_half`) the rows span [0, 1] alone.
Real gather_row_cosine(IN(Atmosphere) atmosphere, Real r, int j, int n, bool upper_half,
                       OUT(Real) weight) {
  Real ratio = atmosphere.bottom_radius / r;
  Real mu_h = upper_half ? Real(0.0) : -safe_sqrt(Real(1.0) - ratio * ratio);
  int half_rows = upper_half ? n : n / 2;
  bool above = upper_half || j < half_rows;
  int k = above ? j : j - half_rows;
  Real s0 = Real(k) / Real(half_rows), s1 = Real(k + 1) / Real(half_rows);
  Real sm = Real(0.5) * (s0 + s1);
  Real span = above ? Real(1.0) - mu_h : Real(1.0) + mu_h;
  weight = span * (s1 * s1 - s0 * s0) / (upper_half ? Real(1.0) : Real(2.0));
  return above ? mu_h + span * sm * sm : mu_h - span * sm * sm;
}

// Light l arriving along d (local frame), added to the moments (or, for
// the ground's irradiance, l d.z to the mean alone).
void add_to_moments(INOUT(FieldMoments) f, IN(Real3) l, IN(Real3) d, bool ground_irradiance) {
  if (ground_irradiance) {
    f.part[kFieldMean] += l * max(d.z, Real(0.0));
    return;
  }
  for (int k = 0; k < kFieldParts; ++k) f.part[k] += field_basis(k, d.x, d.y, d.z) * l;
}

// The azimuths of row j of n, over [0, pi] alone: the light is the same
// along the mirror image of a direction in the sun's vertical plane
// (y -> -y) and the moments are even in y, so that azimuths pair off and
// one of each pair counts twice (`mirror`); 0 and pi are their own images.
// Rows alternate between (i + 1/2) 2 pi / n and i 2 pi / n. With n = 8,
// cos(4 phi) is zero on every azimuth of the first kind and one in size on
// the second; alternating, the degree-4 terms come out right on average,
// as they do with 12 or 16 azimuths a row (Mars sunset 7.9 / 7.6 / 5.4 %
// with the first kind alone, 7.0 / 6.6 / 4.8 % with 12 or 16 a row).
int traced_azimuths(int j, int n) { return (j & 1) == 0 ? n / 2 : n / 2 + 1; }

Real row_azimuth(int j, int i, int n, OUT(Real) mirror) {
  bool offset = (j & 1) == 0;
  mirror = offset || (i > 0 && i < n / 2) ? Real(2.0) : Real(1.0);
  return Real(2.0) * kPi * (Real(i) + (offset ? Real(0.5) : Real(0.0))) / Real(n);
}

// The cosine to the sun of row j of n whose shares of Henyey-Greenstein's
// g are equal: its inverse distribution at the row's middle.
Real henyey_greenstein_row_cosine(Real g, int j, int n) {
  Real xi = (Real(j) + Real(0.5)) / Real(n);
  if (abs(g) < Real(1e-3)) return Real(2.0) * xi - Real(1.0);
  Real k = (Real(1.0) - g * g) / (Real(1.0) - g + Real(2.0) * g * xi);
  return clamp_cosine((Real(1.0) + g * g - k * k) / (Real(2.0) * g));
}

// The moments of the light arriving at (r, mu_s) from `source_kind` (see
// FieldMoments); for the ground (`ground_irradiance`) the mean is instead
// the irradiance, over the cosine-weighted upper hemisphere.
//
// The first order's Mie light is the sun's glow: its phase peaks within a
// few degrees of the sun, where n x n directions packed toward the horizon
// put hardly a ray (on Mars, g = 0.75, the noon sky came out 7-9 % off
// with 8 x 8 and 2.7 % with 64 x 64). Its directions are drawn instead
// from rows of equal share of Henyey-Greenstein about the sun, each weighed
// by Cornette-Shanks over Henyey-Greenstein, 3 (1 + nu^2) / (2 (2 + g^2)):
// what is left to integrate, the light's path through the air, changes
// slowly with direction. Rayleigh and the ground keep the horizon's rows.
FieldMoments gather_order(IN(Atmosphere) atmosphere, Real r, Real mu_s, int source_kind,
                          bool ground_irradiance) {
  Real3 o = Real3(0.0, 0.0, r);
  Real3 sun_dir = Real3(safe_sqrt(Real(1.0) - mu_s * mu_s), Real(0.0), mu_s);
  FieldMoments f;
  for (int k = 0; k < kFieldParts; ++k) f.part[k] = Real3(0.0);
  bool first_order = source_kind == kSourceFirstOrder;
  int kind = first_order ? kSourceSunRayleigh : source_kind;
  const int n = kMultipleScatteringDirectionsSqrt;
  for (int j = 0; j < n; ++j) {
    Real weight;
    Real cos_theta = gather_row_cosine(atmosphere, r, j, n, ground_irradiance, weight);
    Real sin_theta = safe_sqrt(Real(1.0) - cos_theta * cos_theta);
    for (int i = 0; i < traced_azimuths(j, n); ++i) {
      Real mirror;
      Real phi = row_azimuth(j, i, n, mirror);
      Real3 d = Real3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
      Real t_end;
      bool hits_ground;
      ray_extent_inside(atmosphere, o, d, t_end, hits_ground);
      Real3 luminance, transmittance, f_ms;
      integrate_along(atmosphere, o, d, Real(0.0), t_end, sun_dir, kMultipleScatteringSteps, kind,
                      kind == kSourceNextOrder ? kFieldInterpolated : kFieldEachStep,
                      hits_ground && !ground_irradiance, luminance, transmittance, f_ms);
      add_to_moments(f, (mirror * weight / Real(n)) * luminance, d, ground_irradiance);
    }
  }
  if (first_order) {
    // About the sun: (sun_dir, across, side) orthonormal; sun_dir has no y.
    Real3 across = Real3(0.0, 1.0, 0.0);
    Real3 side = Real3(sun_dir.z, Real(0.0), -sun_dir.x);
    Real g = atmosphere.mie_g;
    // Over the whole sphere the shares sum to 1; the ground's hemisphere
    // rows above sum to 1 over half of it.
    Real share = (ground_irradiance ? Real(2.0) : Real(1.0)) / Real(n * n);
    for (int j = 0; j < n; ++j) {
      Real nu = henyey_greenstein_row_cosine(g, j, n);
      Real sin_nu = safe_sqrt(Real(1.0) - nu * nu);
      // The phase over the rows' Henyey-Greenstein density: 1 for it, the
      // Cornette-Shanks factor for that one.
      Real weight = atmosphere.mie_phase_hg > Real(0.5)
                        ? Real(1.0)
                        : Real(1.5) * (Real(1.0) + nu * nu) / (Real(2.0) + g * g);
      for (int i = 0; i < traced_azimuths(j, n); ++i) {
        Real mirror;
        Real phi = row_azimuth(j, i, n, mirror);
        Real3 d = nu * sun_dir + sin_nu * (cos(phi) * side + sin(phi) * across);
        if (ground_irradiance && d.z <= Real(0.0)) continue;
        Real t_end;
        bool hits_ground;
        ray_extent_inside(atmosphere, o, d, t_end, hits_ground);
        Real3 luminance, transmittance, f_ms;
        integrate_scattering(atmosphere, o, d, Real(0.0), t_end, sun_dir,
                             kMultipleScatteringSteps, kSourceSunMie, false, luminance,
                             transmittance, f_ms);
        // The mean over the sphere of L = K p is the mean over these
        // directions of K times the weight, over 4 pi.
        add_to_moments(f, mirror * share * weight / (Real(4.0) * kPi) * luminance, d,
                       ground_irradiance);
      }
    }
  }
  // Irradiance: int L cos dw over the hemisphere, 2 pi times the mean.
  if (ground_irradiance) f.part[kFieldMean] *= Real(2.0) * kPi;
  return f;
}

// The ground as the irradiance integrals see it: a hair above the bottom
// sphere, so that the horizontal directions do not start inside it.
Real ground_gather_radius(IN(Atmosphere) atmosphere) {
  return atmosphere.bottom_radius + Real(1.0);
}

// The sum x_sum of orders 1 to N and the geometric tail of the orders
// beyond, x_N q / (1 - q), whose ratio q is that of the last two orders'
// mean radiance j_(N-1), j_N, per channel (a moment takes the tail of its
// mean). The ratio still grows with the order: with N = 3 the tail left
// the blue ground's sky light 1 % below N = 5; with N = 4, 0.3 %.
Real3 with_geometric_tail(IN(Real3) j_before_last, IN(Real3) j_last, IN(Real3) x_sum,
                          IN(Real3) x_last) {
  Real3 q = clamp(j_last / max(j_before_last, Real3(1e-30)), Real3(0.0), Real3(0.9));
  return x_sum + x_last * q / (Real3(1.0) - q);
}
