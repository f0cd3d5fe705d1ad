#include "sim/eclipse.h"

#include "sim/ephemeris.h"
#include "sim/sun_ephemeris.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <vector>

namespace planet {

namespace {

constexpr double kScanWindow = 3.0 * 3600.0;  // seconds each side of `near`
constexpr double kScanStep = 300.0;
constexpr double kTimeTolerance = 1e-3;  // seconds

// Golden-section search for the minimum of f on [lo, hi].
template <class F>
double minimise(F f, double lo, double hi) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = hi - r * (hi - lo), b = lo + r * (hi - lo);
  double fa = f(a), fb = f(b);
  while (hi - lo > kTimeTolerance) {
    if (fa < fb) {
      hi = b, b = a, fb = fa;
      a = hi - r * (hi - lo), fa = f(a);
    } else {
      lo = a, a = b, fa = fb;
      b = lo + r * (hi - lo), fb = f(b);
    }
  }
  return 0.5 * (lo + hi);
}

// The root of f between a and b, where f changes sign, by bisection.
template <class F>
double root(F f, double a, double b) {
  double fa = f(a);
  while (std::abs(b - a) > kTimeTolerance) {
    double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m, fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// The scan's coarse minimum of f over near +- kScanWindow, refined; none
// where the smallest value lies at the window's edge (the minimum is then
// outside it).
template <class F>
std::optional<double> minimum_near(F f, UtcSeconds near) {
  double best_t = near - kScanWindow, best = f(best_t);
  for (double t = near - kScanWindow + kScanStep; t <= near + kScanWindow; t += kScanStep) {
    double v = f(t);
    if (v < best) best = v, best_t = t;
  }
  if (std::abs(best_t - near) >= kScanWindow) return std::nullopt;
  return minimise(f, best_t - kScanStep, best_t + kScanStep);
}

// The Moon's shadow at an instant, GCRS metres: the axis runs from the
// Sun's centre through the Moon's.
struct Shadow {
  glm::dvec3 sun, moon, axis;
  double sun_moon = 0;  // |sun - moon|
};

Shadow shadow_at(UtcSeconds t) {
  Shadow s;
  s.sun = sun_pos_gcrs(t);
  s.moon = moon_pos_gcrs(t);
  s.sun_moon = glm::length(s.moon - s.sun);
  s.axis = (s.moon - s.sun) / s.sun_moon;
  return s;
}

// The Earth's centre seen from the axis: the perpendicular from the axis.
glm::dvec3 centre_off_axis(const Shadow& s) {
  glm::dvec3 to_centre = -s.moon;
  return to_centre - glm::dot(to_centre, s.axis) * s.axis;
}

// How far a point lies outside the Moon's umbral (or antumbral) cone,
// metres (negative inside), and whether the cone is the umbra there. The
// cone touches both the Sun and the Moon (radius k a) from outside; its
// vertex lies x_v = R_moon / sin f2 beyond the Moon, and its radius at a
// distance x along the axis from the Moon is (x_v - x) tan f2: positive up
// to the vertex (the umbra: total), negative past it (the antumbra:
// annular).
struct ConeDistance {
  double outside = 0;
  bool umbra = false;
};
ConeDistance umbra_distance(const Shadow& s, const glm::dvec3& p, const EclipseConstants& c) {
  double r_moon = c.moon_k_umbra * c.earth_radius;
  double sin_f2 = (c.sun_radius - r_moon) / s.sun_moon;
  double tan_f2 = sin_f2 / std::sqrt(1.0 - sin_f2 * sin_f2);
  double x_vertex = r_moon / sin_f2;
  glm::dvec3 from_moon = p - s.moon;
  double x = glm::dot(from_moon, s.axis);
  double rho = glm::length(from_moon - x * s.axis);
  double radius = (x_vertex - x) * tan_f2;
  return {rho - std::abs(radius), radius > 0};
}

// The penumbra's radius in the plane through the Earth's centre across the
// axis (the Canon's l1), metres: its cone touches the Sun and the Moon from
// either side, with the vertex between them.
double penumbra_radius_at_centre(const Shadow& s, const EclipseConstants& c) {
  double r_moon = c.moon_k_penumbra * c.earth_radius;
  double sin_f1 = (c.sun_radius + r_moon) / s.sun_moon;
  double tan_f1 = sin_f1 / std::sqrt(1.0 - sin_f1 * sin_f1);
  double x = glm::dot(-s.moon, s.axis);
  return (x + r_moon / sin_f1) * tan_f1;
}

// Where the line p + s d first meets the ellipsoid (s >= 0), or nothing.
std::optional<glm::dvec3> hit_ellipsoid(const glm::dvec3& p, const glm::dvec3& d,
                                        const EclipseConstants& c) {
  // Stretching z by a/b makes the ellipsoid a sphere of radius a.
  double stretch = 1.0 / (1.0 - c.earth_flattening);
  glm::dvec3 ps(p.x, p.y, p.z * stretch), ds(d.x, d.y, d.z * stretch);
  double qa = glm::dot(ds, ds), qb = 2.0 * glm::dot(ps, ds);
  double qc = glm::dot(ps, ps) - c.earth_radius * c.earth_radius;
  double disc = qb * qb - 4.0 * qa * qc;
  if (disc < 0) return std::nullopt;
  double s = (-qb - std::sqrt(disc)) / (2.0 * qa);
  if (s < 0) return std::nullopt;
  return p + s * d;
}

// The ellipsoid's point straight below (or above) p, seen from the centre.
glm::dvec3 to_ellipsoid(const glm::dvec3& p, const EclipseConstants& c) {
  double b = c.earth_radius * (1.0 - c.earth_flattening);
  double a2 = c.earth_radius * c.earth_radius;
  return p / std::sqrt((p.x * p.x + p.y * p.y) / a2 + p.z * p.z / (b * b));
}

// Where the axis meets the ground at t, Earth-fixed metres.
std::optional<glm::dvec3> centre_on_ground(UtcSeconds t, const EclipseConstants& c) {
  Shadow s = shadow_at(t);
  glm::dmat3 itrs = itrs_from_gcrs(t);
  return hit_ellipsoid(itrs * s.moon, itrs * s.axis, c);
}

// The path's width across its centre line at the instant t, metres: the
// umbra's footprint on the ellipsoid, moving along the track, sweeps a band
// as wide as the footprint's extent across the track (its support in
// either direction), found on rays from the centre every half degree.
double path_width(UtcSeconds t, const glm::dvec3& centre_itrs, const Geodesy& geodesy,
                  const EclipseConstants& c) {
  Shadow s = shadow_at(t);
  glm::dmat3 gcrs = glm::transpose(itrs_from_gcrs(t));
  glm::dmat3 enu = geodesy.body_from_enu(geodesy.geodetic_from_body(centre_itrs));
  glm::dvec3 up = enu[2];
  auto before = centre_on_ground(t - 30.0, c), after = centre_on_ground(t + 30.0, c);
  if (!before || !after) return 0.0;
  glm::dvec3 track = *after - *before;
  track = glm::normalize(track - glm::dot(track, up) * up);
  glm::dvec3 across = glm::cross(up, track);
  auto outside = [&](const glm::dvec3& dir, double r) {
    return umbra_distance(s, gcrs * to_ellipsoid(centre_itrs + r * dir, c), c).outside;
  };
  double left = 0, right = 0;
  for (int i = 0; i < 720; ++i) {
    double phi = glm::radians(0.5 * i);
    glm::dvec3 dir = std::cos(phi) * track + std::sin(phi) * across;
    double r = root([&](double rr) { return outside(dir, rr); }, 0.0, 2.0e6);
    double side = glm::dot(to_ellipsoid(centre_itrs + r * dir, c) - centre_itrs, across);
    left = std::max(left, side);
    right = std::max(right, -side);
  }
  return left + right;
}

// How long the place (Earth-fixed) stays inside the cone about t.
double central_duration(UtcSeconds t, const glm::dvec3& place_itrs, const EclipseConstants& c) {
  auto outside = [&](double tt) {
    glm::dvec3 p = glm::transpose(itrs_from_gcrs(tt)) * place_itrs;
    return umbra_distance(shadow_at(tt), p, c).outside;
  };
  // No central eclipse lasts past 7.5 minutes: 10 minutes each side holds it.
  if (outside(t) > 0) return 0.0;
  return root(outside, t, t + 600.0) - root(outside, t - 600.0, t);
}

}  // namespace

std::optional<SolarEclipse> solar_eclipse(UtcSeconds near, const EclipseConstants& c) {
  auto miss = [&](double t) {
    Shadow s = shadow_at(t);
    // Only a Moon on the Sun's side casts its shadow toward the Earth.
    if (glm::dot(s.moon, s.sun) <= 0) return 1e12;
    return glm::length(centre_off_axis(s));
  };
  auto greatest = minimum_near(miss, near);
  if (!greatest) return std::nullopt;
  SolarEclipse e;
  e.greatest = *greatest;
  Shadow s = shadow_at(e.greatest);
  glm::dvec3 off = centre_off_axis(s);
  double distance = glm::length(off);
  if (glm::dot(s.moon, s.sun) <= 0 || distance > c.earth_radius + penumbra_radius_at_centre(s, c)) {
    return std::nullopt;
  }
  // The axis passes the centre on the side opposite `off`.
  e.gamma = (off.z > 0 ? -1.0 : 1.0) * distance / c.earth_radius;
  auto point = centre_on_ground(e.greatest, c);
  if (!point) return e;
  e.central = true;
  Geodesy geodesy(Ellipsoid{c.earth_radius, c.earth_flattening});
  e.point = geodesy.geodetic_from_body(*point);
  glm::dmat3 itrs = itrs_from_gcrs(e.greatest);
  e.total = umbra_distance(s, glm::transpose(itrs) * *point, c).umbra;
  HorizonAngles sun =
      horizon_angles(glm::normalize(itrs * s.sun - *point), e.point.lat, e.point.lon);
  e.sun_altitude = sun.elevation;
  e.sun_azimuth = sun.azimuth;
  e.path_width = path_width(e.greatest, *point, geodesy, c);
  e.central_duration = central_duration(e.greatest, *point, c);
  return e;
}

namespace {

// The Earth's shadow at the Moon's distance, seen from the Earth's centre:
// angles in radians.
struct EarthShadow {
  double sigma = 0;                // the Moon's centre from the shadow's centre
  double umbra = 0, penumbra = 0;  // radii, Danjon's rule
  double moon = 0;                 // the Moon's semi-diameter
  glm::dvec3 moon_dir, centre_dir;
};

EarthShadow earth_shadow_at(UtcSeconds t, const EclipseConstants& c) {
  glm::dvec3 sun = sun_pos_gcrs(t), moon = moon_pos_gcrs(t);
  EarthShadow e;
  e.moon_dir = glm::normalize(moon);
  e.centre_dir = -glm::normalize(sun);
  e.sigma = std::acos(glm::clamp(glm::dot(e.moon_dir, e.centre_dir), -1.0, 1.0));
  double pi_moon = std::asin(c.earth_radius / glm::length(moon));
  double pi_sun = std::asin(c.earth_radius / glm::length(sun));
  double s_sun = std::asin(c.sun_radius / glm::length(sun));
  e.umbra = c.danjon_factor * pi_moon + pi_sun - s_sun;
  e.penumbra = c.danjon_factor * pi_moon + pi_sun + s_sun;
  e.moon = std::asin(c.moon_k_mean * c.earth_radius / glm::length(moon));
  return e;
}

}  // namespace

std::optional<LunarEclipse> lunar_eclipse(UtcSeconds near, const EclipseConstants& c) {
  auto sigma = [&](double t) { return earth_shadow_at(t, c).sigma; };
  auto greatest = minimum_near(sigma, near);
  if (!greatest) return std::nullopt;
  LunarEclipse e;
  e.greatest = *greatest;
  EarthShadow g = earth_shadow_at(e.greatest, c);
  if (g.sigma > g.penumbra + g.moon) return std::nullopt;
  double moon_distance = glm::length(moon_pos_gcrs(e.greatest));
  e.gamma = (g.moon_dir.z > g.centre_dir.z ? 1.0 : -1.0) * moon_distance * std::sin(g.sigma) /
            c.earth_radius;
  e.umbral_magnitude = (g.umbra + g.moon - g.sigma) / (2.0 * g.moon);
  e.penumbral_magnitude = (g.penumbra + g.moon - g.sigma) / (2.0 * g.moon);
  // Each contact: the Moon's centre at a given distance from the shadow's;
  // the distance grows monotonically away from greatest eclipse, which
  // never lies more than 4 hours from the penumbra's contacts.
  auto contacts = [&](auto radius, std::optional<UtcSeconds>& begin,
                      std::optional<UtcSeconds>& end) {
    auto excess = [&](double t) {
      EarthShadow s = earth_shadow_at(t, c);
      return s.sigma - radius(s);
    };
    if (excess(e.greatest) > 0) return;
    begin = root(excess, e.greatest - 4.0 * 3600.0, e.greatest);
    end = root(excess, e.greatest, e.greatest + 4.0 * 3600.0);
  };
  contacts([](const EarthShadow& s) { return s.penumbra + s.moon; }, e.p1, e.p4);
  contacts([](const EarthShadow& s) { return s.umbra + s.moon; }, e.u1, e.u4);
  contacts([](const EarthShadow& s) { return s.umbra - s.moon; }, e.u2, e.u3);
  return e;
}

Eclipse find_eclipse(UtcSeconds day, const EclipseConstants& c) {
  // Each eclipse's greatest phase falls within minutes of the Moon's least
  // angle from the Sun (new Moon) or from the point opposite it (full
  // Moon): found on a half-hour grid over the day and 3 hours either side,
  // it is the middle of the 6 hours that solar_eclipse and lunar_eclipse
  // search.
  auto syzygies = [&](double sign) {
    auto angle = [sign](double t) {
      glm::dvec3 moon = glm::normalize(moon_pos_gcrs(t));
      glm::dvec3 sun = glm::normalize(sun_pos_gcrs(t));
      return std::acos(glm::clamp(glm::dot(moon, sign * sun), -1.0, 1.0));
    };
    std::vector<UtcSeconds> found;
    const double step = 1800.0;
    double t0 = day - 3.0 * 3600.0, before = angle(t0 - step), now = angle(t0);
    for (double t = t0; t <= day + 27.0 * 3600.0; t += step) {
      double after = angle(t + step);
      if (now < before && now <= after) found.push_back(t);
      before = now, now = after;
    }
    return found;
  };
  Eclipse found;
  auto on_day = [&](UtcSeconds t) { return t >= day && t < day + 86400.0; };
  for (UtcSeconds t : syzygies(1.0)) {
    auto e = solar_eclipse(t, c);
    if (e && on_day(e->greatest)) found.solar = e;
  }
  for (UtcSeconds t : syzygies(-1.0)) {
    auto e = lunar_eclipse(t, c);
    if (e && on_day(e->greatest)) found.lunar = e;
  }
  return found;
}

}  // namespace planet
