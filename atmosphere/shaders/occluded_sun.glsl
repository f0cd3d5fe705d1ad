// The sun partly covered by the Moon (the shared math: see
// definitions.glsl): the visible share of the limb-darkened disk's flux
// (sun.glsl's law), per channel, at a point. Every point that takes
// sunlight multiplies it by this share, so that the penumbra darkens
// smoothly and the umbra is black but for the sky's light.
//
// On the sky about the sun, in units of the sun's angular radius, the
// disk is the unit circle and the Moon a circle of radius rho whose centre
// is d from the sun's (both small angles: the flat sky errs by their
// square, under 1e-5). A ring of the disk about its centre at radius x is
// wholly covered or wholly clear within |d - rho| and clear beyond
// d + rho; between, kOccludedSunRings rings take each its flux (exact)
// times its covered share of area (exact: differences of the lens area of
// two circles), which is exact where the intensity is constant over a
// ring. With 32 rings, the share is within 0.1 % of a fine integral where
// it exceeds 1 % (0.095 % at worst, a thin ring of an annular eclipse),
// and within 2e-4 of the disk's flux everywhere; 16 rings left 0.13 % and
// 6e-4 (tests/atmosphere/occluded_sun_test.cpp). No overlap, full cover and a
// Moon centred on the sun are exact.
const int kOccludedSunRings = 32;

// The area shared by two circles of radii a and b whose centres are d
// apart: two circular segments (the lens), or the smaller circle whole.
Real circle_overlap_area(Real a, Real b, Real d) {
  if (d >= a + b) return Real(0.0);
  if (d <= abs(a - b)) return kPi * min(a, b) * min(a, b);
  Real cos_a = clamp((d * d + a * a - b * b) / (Real(2.0) * d * a), Real(-1.0), Real(1.0));
  Real cos_b = clamp((d * d + b * b - a * a) / (Real(2.0) * d * b), Real(-1.0), Real(1.0));
  Real kite = (-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b);
  return a * a * acos(cos_a) + b * b * acos(cos_b) - Real(0.5) * safe_sqrt(kite);
}

// The share of the disk's flux within x disk radii of its centre: with
// I = mu^alpha and mu^2 = 1 - x^2, int_0^x I 2x dx / int_0^1 I 2x dx
// = 1 - (1 - x^2)^(alpha / 2 + 1).
Real3 sun_flux_within(Real x) {
  Real mu2 = max(Real(1.0) - x * x, Real(0.0));
  return Real3(1.0) - pow(Real3(mu2), kLimbDarkening * Real(0.5) + Real3(1.0));
}

// The visible share of the sun's flux at a point from which the sun's
// centre lies toward sun_dir (unit) with angular radius sun_radius, and the
// Moon's centre at moon_centre (relative to the point, metres) with radius
// moon_radius. 1 with no overlap, 0 in the umbra (or inside the Moon).
Real3 occluded_sun_fraction(Real3 sun_dir, Real sun_radius, Real3 moon_centre, Real moon_radius) {
  Real distance = length(moon_centre);
  if (distance <= moon_radius) return Real3(0.0);
  Real3 moon_dir = moon_centre / distance;
  // atan of sine over cosine keeps a small separation exact, where acos of
  // the cosine loses it in float.
  Real d = atan(length(cross(sun_dir, moon_dir)), dot(sun_dir, moon_dir)) / sun_radius;
  Real rho = asin(moon_radius / distance) / sun_radius;
  if (d >= Real(1.0) + rho) return Real3(1.0);
  if (rho >= d + Real(1.0)) return Real3(0.0);
  Real inner = abs(d - rho);
  Real outer = min(Real(1.0), d + rho);
  Real3 covered = rho > d ? sun_flux_within(inner) : Real3(0.0);
  Real x0 = inner;
  Real3 flux0 = sun_flux_within(x0);
  Real area0 = circle_overlap_area(x0, rho, d);
  for (int i = 1; i <= kOccludedSunRings; ++i) {
    Real x1 = mix(inner, outer, Real(i) / Real(kOccludedSunRings));
    Real3 flux1 = sun_flux_within(x1);
    Real area1 = circle_overlap_area(x1, rho, d);
    Real ring = kPi * (x1 * x1 - x0 * x0);
    if (ring > Real(0.0)) {
      covered += (flux1 - flux0) * clamp((area1 - area0) / ring, Real(0.0), Real(1.0));
    }
    x0 = x1;
    flux0 = flux1;
    area0 = area1;
  }
  return clamp(Real3(1.0) - covered, Real3(0.0), Real3(1.0));
}

// The sun's disk seen along the ray from o (unit direction d) is hidden
// where the ray meets the Moon's sphere ahead (its centre and radius, as
// above; none while the radius is 0).
bool moon_hides_sun(Real3 o, Real3 d, Real3 moon_centre, Real moon_radius) {
  Real t_near, t_far;
  return moon_radius > Real(0.0) && ray_sphere(o - moon_centre, d, moon_radius, t_near, t_far) &&
         t_far > Real(0.0);
}
