// O'Neil 2005, "Accurate Atmospheric Scattering" (GPU Gems 2, ch. 16):
// single scattering evaluated at a few samples along each ray, the optical
// depth to the sun and to the camera from a "scale function" instead of a
// second march. Written in the common subset of GLSL and C++ (see
// definitions.glsl): the technique's shaders include it after the shared
// math, and atmosphere/math/oneil_math.h compiles it in double, where the
// scale function is fitted and its error measured.
//
// The chapter's observation: for one exponential component of scale height
// H, the column density (the integral of the density along a ray, metres)
// from altitude h along zenith cosine mu to the top factors nearly as
//   column(h, mu) ~ H exp(-h / H) scale(mu),
// and for the Earth-like ratio it was made for (H a quarter of the
// atmosphere's thickness, the thickness 2.5 % of the radius) it fitted
//   scale(mu) = exp(-0.00287 + x (0.459 + x (3.83 + x (-6.80 + x 5.25)))),
// x = 1 - mu, in multiples of the vertical column H. That form cannot hold
// in general: near the top the column falls to 0 faster than exp(-h / H)
// (the shell ends), and on a small body the horizon's path depends on the
// radius (it grows as sqrt(r / H)). The fitted form keeps the chapter's
// shape and carries both in closed form:
//   column(h, mu) = V(h) G(h, mu) exp(Q(v, z)),  mu >= 0,
// V(h) = H (exp(-h / H) - exp(-thickness / H)) the vertical column, exact;
// G the path length through a thin shell of thickness D = H L / (H + L)
// above r (L = top - r) divided by D, which is 1 straight up, ~1 / mu for
// mu >> sqrt(D / r) and saturates at sqrt(2 r / D) at the horizon, as the
// exponential column does at sqrt(pi r / (2 H)); and Q a polynomial of
// v^1..v^kOneilXTerms times z^0..z^(kOneilYTerms - 1), v and z the
// chapter's x and the height recast (oneil_horizon_variable,
// oneil_height_variable), so that Q = 0 and the column is exact straight
// up. Q's coefficients are fitted per body and component when the model
// loads (atmosphere/math/oneil_math.h): a closed-form core and a small
// polynomial rather than a 2D table, so that the technique stays the
// chapter's (a few arithmetic operations per evaluation, no texture) and
// `planet probe oneil-fit` can print what the shader evaluates. A ray below
// the horizontal that misses the ground is split at its perigee, as
// Chapman's function is: two upward halves from the perigee, less the
// upward one from the start.
//
// The constants and the scale function's type are in oneil_definitions.glsl.
// The includer declares Real3 eclipse_sun_share(IN(Real3) p, IN(Real3)
// sun_dir), the visible share of the sun at p with the Moon before it
// (occluded_sun.glsl; 1 but in an eclipse, and on the CPU).

// The chapter's polynomial, in multiples of the vertical column H.
Real oneil_chapter_scale(Real mu) {
  Real x = Real(1.0) - mu;
  return exp(Real(-0.00287) +
             x * (Real(0.459) + x * (Real(3.83) + x * (Real(-6.80) + x * Real(5.25)))));
}

// The thin shell's path ratio G (see above), written without the
// difference of squares that loses the short path near the top in floats:
// the path to radius r + D is D (2r + D) / (r mu + sqrt(r^2 mu^2 + D (2r + D))).
Real oneil_shell_path_ratio(Real r, Real mu, Real depth) {
  Real d = max(depth, Real(1e-3));
  return (Real(2.0) * r + d) / (r * mu + sqrt(r * r * mu * mu + d * (Real(2.0) * r + d)));
}

Real oneil_polynomial(IN(OneilScale) s, Real x, Real y) {
  Real sum = Real(0.0);
  for (int i = kOneilXTerms - 1; i >= 0; --i) {
    Real row = Real(0.0);
    for (int j = kOneilYTerms - 1; j >= 0; --j) row = row * y + s.c[i * kOneilYTerms + j];
    sum = (sum + row) * x;
  }
  return sum;
}

// The fitted polynomial's variable in place of the chapter's x = 1 - mu:
// v = (1 - mu) / (1 + k mu), k = sqrt(r / (2 D)) with D the shell depth of
// G, 0 straight up and 1 at the horizontal. The column's ratio to V G
// changes within mu ~ sqrt(2 D / r) of the horizontal (Earth's Mie near the
// ground: 0.02; just under the top, far less), where x = 1 - mu leaves a
// polynomial of degree 6 no room (2-10 % worst errors with it); v spreads
// that band over the middle of its range at every height.
Real oneil_horizon_variable(Real r, Real depth, Real mu) {
  Real k = sqrt(r / (Real(2.0) * max(depth, Real(1e-3))));
  return (Real(1.0) - mu) / (Real(1.0) + k * mu);
}

// The fitted polynomial's height variable: 0 at the ground, 1 at the top,
// through the shell depth D = H L / (H + L), L = top - r. Near the top the
// column's ratio to V G goes as 1 - c L / H, which in h / thickness is
// squeezed into the last few hundredths on Earth (thickness / H = 12.5): a
// worst error of 5-7 % there with y = h / thickness, for which D opens up
// the top while keeping the bottom, where only r matters, compact.
Real oneil_height_variable(Real scale_height, Real thickness, Real depth) {
  return Real(1.0) - depth * (scale_height + thickness) / (scale_height * thickness);
}

// The column from radius r along zenith cosine mu >= 0 to the top (fitted kind).
Real oneil_column_up(IN(Atmosphere) atmosphere, IN(OneilScale) s, Real r, Real mu) {
  Real thickness = atmosphere.top_radius - atmosphere.bottom_radius;
  Real h = clamp(r - atmosphere.bottom_radius, Real(0.0), thickness);
  Real left = thickness - h;
  Real H = s.scale_height;
  Real vertical = H * exp(-h / H) * (Real(1.0) - exp(-left / H));
  Real depth = H * left / (H + left);
  Real mu_up = clamp(mu, Real(0.0), Real(1.0));
  Real ratio = oneil_shell_path_ratio(r, mu_up, depth);
  return vertical * ratio *
         exp(oneil_polynomial(s, oneil_horizon_variable(r, depth, mu_up),
                              oneil_height_variable(H, thickness, depth)));
}

// The column from radius r along zenith cosine mu to the top, for a ray that
// does not meet the ground.
Real oneil_column(IN(Atmosphere) atmosphere, IN(OneilScale) s, Real r, Real mu) {
  if (s.kind == kOneilChapter) {
    Real h = max(r - atmosphere.bottom_radius, Real(0.0));
    return s.scale_height * exp(-h / s.scale_height) * oneil_chapter_scale(mu);
  }
  // The column along the mirrored ray serves both cases: written once, a
  // SIMD rasteriser (llvmpipe), which runs every side of a branch, pays for
  // two evaluations instead of three. The perigee's is in a loop run once
  // or not at all: llvmpipe leaves a loop as soon as no lane of its batch
  // is in it, where it would run an if's body for any batch (most rays,
  // the sun's by day and the camera's up from a sample, point up).
  Real column = oneil_column_up(atmosphere, s, r, abs(mu));
  for (int below = mu < Real(0.0) ? 1 : 0; below > 0; --below) {
    Real r_perigee = max(r * sqrt(max(Real(1.0) - mu * mu, Real(0.0))), atmosphere.bottom_radius);
    column = max(Real(2.0) * oneil_column_up(atmosphere, s, r_perigee, Real(0.0)) - column,
                 Real(0.0));
  }
  return column;
}

// The columns (Rayleigh in x, Mie in y) from point p along the unit
// direction d to the top.
Real2 oneil_columns(IN(Atmosphere) atmosphere, IN(OneilScale) rayleigh, IN(OneilScale) mie,
                    IN(Real3) p, IN(Real3) d) {
  Real r = length(p);
  Real mu = clamp_cosine(dot(p, d) / r);
  return Real2(oneil_column(atmosphere, rayleigh, r, mu), oneil_column(atmosphere, mie, r, mu));
}

Real3 oneil_extinction(IN(Atmosphere) atmosphere, IN(Real2) columns) {
  return atmosphere.rayleigh_scattering * columns.x + atmosphere.mie_extinction * columns.y;
}

// The columns between a (distance t_a along the ray o + t d) and b (t_b > t_a).
// On a ray that misses the ground, the columns to the top from a less those
// from b; on one that meets it, the same backwards from b and a, whose rays
// then always miss it.
Real2 oneil_path_columns(IN(Atmosphere) atmosphere, IN(OneilScale) rayleigh, IN(OneilScale) mie,
                         IN(Real3) o, IN(Real3) d, bool hits_ground, Real t_a, Real t_b) {
  Real3 a = o + t_a * d;
  Real3 b = o + t_b * d;
  Real2 column = hits_ground ? oneil_columns(atmosphere, rayleigh, mie, b, -d) -
                                   oneil_columns(atmosphere, rayleigh, mie, a, -d)
                             : oneil_columns(atmosphere, rayleigh, mie, a, d) -
                                   oneil_columns(atmosphere, rayleigh, mie, b, d);
  return max(column, Real2(0.0));
}

// Single scattering along o + t d, t from t_a to t_b, at `samples`
// points: the light scattered toward the
// camera per unit phase function, Rayleigh and Mie apart so that the
// phase functions can be applied per pixel, times the solar irradiance; and
// the transmittance from t_a to t_b. The sun's column at each sample from
// the scale function; a sample in the planet's shadow receives nothing.
// hits_ground: the ray from o meets the bottom sphere.
void oneil_single_scattering(IN(Atmosphere) atmosphere, IN(OneilScale) rayleigh,
                             IN(OneilScale) mie, IN(Real3) o, IN(Real3) d, bool hits_ground,
                             Real t_a, Real t_b, IN(Real3) sun_dir, int samples,
                             OUT(Real3) rayleigh_light, OUT(Real3) mie_light,
                             OUT(Real3) transmittance) {
  rayleigh_light = Real3(0.0);
  mie_light = Real3(0.0);
  Real3 a = o + t_a * d;
  // The camera side's columns, once: each sample's column to the camera is
  // their difference with the sample's own.
  Real2 a_columns = hits_ground ? oneil_columns(atmosphere, rayleigh, mie, a, -d)
                                : oneil_columns(atmosphere, rayleigh, mie, a, d);
  // The samples crowd (s = L u^2 from each end) toward the ray's lowest
  // point, where the air is densest: the chapter's evenly spaced samples
  // suit its shell of four scale heights, but on Earth's (12.5 of
  // Rayleigh's) five of them left the zenith's light 22 % short.
  Real t_low = clamp(-dot(o, d), t_a, t_b);
  Real before = t_low - t_a, after = t_b - t_low;
  int samples_before = before <= Real(0.0)  ? 0
                       : after <= Real(0.0) ? samples
                                            : max(samples / 2, 1);
  int samples_after = samples - samples_before;
  for (int i = 0; i < samples; ++i) {
    bool first = i < samples_before;
    int k = first ? i : i - samples_before;
    int n = first ? samples_before : samples_after;
    Real span = first ? before : after;
    Real u = (Real(k) + Real(0.5)) / Real(n);
    // From the lowest point outward: u = 0 there.
    Real s = span * u * u;
    Real ds = span * Real(2.0) * u / Real(n);
    Real3 p = o + (first ? t_low - s : t_low + s) * d;
    Real r = length(p);
    Real mu_s = clamp_cosine(dot(p, sun_dir) / r);
    if (ray_intersects_ground(atmosphere, r, mu_s)) continue;
    Real h = max(r - atmosphere.bottom_radius, Real(0.0));
    Real2 p_columns = hits_ground ? oneil_columns(atmosphere, rayleigh, mie, p, -d)
                                  : oneil_columns(atmosphere, rayleigh, mie, p, d);
    Real2 to_camera = max(hits_ground ? p_columns - a_columns : a_columns - p_columns, Real2(0.0));
    Real2 to_sun = Real2(oneil_column(atmosphere, rayleigh, r, mu_s),
                         oneil_column(atmosphere, mie, r, mu_s));
    // In an eclipse, the Moon's share of the sun at the sample (the
    // includer's; 1 exactly with no Moon, so that it changes no other sky).
    Real3 attenuation = exp(-oneil_extinction(atmosphere, to_camera + to_sun)) *
                        eclipse_sun_share(p, sun_dir);
    rayleigh_light += exp(-h / rayleigh.scale_height) * ds * attenuation;
    mie_light += exp(-h / mie.scale_height) * ds * attenuation;
  }
  rayleigh_light *= atmosphere.rayleigh_scattering * atmosphere.solar_irradiance;
  mie_light *= atmosphere.mie_scattering * atmosphere.solar_irradiance;
  transmittance = exp(-oneil_extinction(
      atmosphere, oneil_path_columns(atmosphere, rayleigh, mie, o, d, hits_ground, t_a, t_b)));
}
