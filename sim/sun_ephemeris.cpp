#include "sim/sun_ephemeris.h"

#include "core/error.h"
#include "core/json_reader.h"
#include "sim/mars24.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace planet {

namespace {

constexpr double kSecondsPerDay = 86400.0;
// Mean obliquity of the ecliptic at J2000 (Meeus eq. 22.2 at T = 0).
constexpr double kObliquityJ2000Deg = 23.4392911;

double deg_sin(double deg) { return std::sin(glm::radians(deg)); }
double deg_cos(double deg) { return std::cos(glm::radians(deg)); }

}  // namespace

EarthSun earth_sun(UtcSeconds utc) {
  // Julian centuries of terrestrial time since J2000 (Meeus eq. 25.1).
  const double t = (utc + tt_minus_utc(utc)) / (kSecondsPerDay * 36525.0);
  // Geometric mean longitude and mean anomaly, degrees (eq. 25.2, 25.3).
  const double l0 = 280.46646 + t * (36000.76983 + t * 0.0003032);
  const double m = 357.52911 + t * (35999.05029 - t * 0.0001537);
  const double e = 0.016708634 - t * (0.000042037 + t * 0.0000001267);
  // Equation of the centre.
  const double c = (1.914602 - t * (0.004817 + t * 0.000014)) * deg_sin(m) +
                   (0.019993 - 0.000101 * t) * deg_sin(2 * m) + 0.000289 * deg_sin(3 * m);
  const double true_longitude = l0 + c;
  const double true_anomaly = m + c;
  // Apparent longitude: aberration and nutation in longitude (eq. 25.8 area).
  const double omega = 125.04 - 1934.136 * t;
  const double lambda = true_longitude - 0.00569 - 0.00478 * deg_sin(omega);
  // Obliquity: mean (eq. 22.2) corrected for nutation (eq. 25.8).
  const double eps0 =
      23.0 + (26.0 + (21.448 - t * (46.8150 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
  const double eps = eps0 + 0.00256 * deg_cos(omega);
  EarthSun sun;
  sun.right_ascension = std::atan2(deg_cos(eps) * deg_sin(lambda), deg_cos(lambda));
  sun.declination = std::asin(deg_sin(eps) * deg_sin(lambda));
  // Eq. 25.5.
  sun.distance_au = 1.000001018 * (1 - e * e) / (1 + e * deg_cos(true_anomaly));
  return sun;
}

std::string SunEphemeris::name() const {
  switch (model) {
    case Model::kEarth:
      return "earth";
    case Model::kMars24:
      return "mars24";
    case Model::kCircularOrbit:
      return "circular_orbit";
    case Model::kNone:
      break;
  }
  return "none";
}

SunEphemeris parse_ephemeris(JsonObject ephemeris) {
  SunEphemeris e;
  std::string model = ephemeris.string("model");
  if (model == "earth") {
    e.model = SunEphemeris::Model::kEarth;
  } else if (model == "mars24") {
    e.model = SunEphemeris::Model::kMars24;
  } else if (model == "circular_orbit") {
    e.model = SunEphemeris::Model::kCircularOrbit;
    e.orbit_radius_au = ephemeris.number("orbit_radius_au", 1e-3, 1e4);
    e.orbit_period = ephemeris.number("orbit_period_days", 1e-3, 1e8) * kSecondsPerDay;
    e.longitude_j2000 = glm::radians(ephemeris.number("longitude_j2000_deg", -360.0, 360.0));
  } else {
    ephemeris.fail("model",
                   fmt::format("'{}' is not a known model (earth, mars24, circular_orbit)", model));
  }
  ephemeris.finish();
  return e;
}

glm::dvec3 sun_dir_body(const SunEphemeris& ephemeris, const BodyRotation& rotation,
                        UtcSeconds utc) {
  switch (ephemeris.model) {
    case SunEphemeris::Model::kEarth: {
      // Right ascension and declination are of date, and W is the mean
      // sidereal time of date: together they place the sun over Earth.
      EarthSun sun = earth_sun(utc);
      glm::dvec3 dir_icrf(std::cos(sun.declination) * std::cos(sun.right_ascension),
                          std::cos(sun.declination) * std::sin(sun.right_ascension),
                          std::sin(sun.declination));
      return glm::normalize(rotation.body_from_inertial(utc) * rotation.inertial_from_icrf() *
                            dir_icrf);
    }
    case SunEphemeris::Model::kMars24: {
      // The subsolar point is given in planetographic coordinates: the
      // surface normal there points at the sun.
      MarsSun sun = mars_sun(utc);
      return {std::cos(sun.subsolar_lat) * std::cos(sun.subsolar_lon_east),
              std::cos(sun.subsolar_lat) * std::sin(sun.subsolar_lon_east),
              std::sin(sun.subsolar_lat)};
    }
    case SunEphemeris::Model::kCircularOrbit: {
      double turns = utc / ephemeris.orbit_period;
      double body_longitude =
          ephemeris.longitude_j2000 + 2.0 * glm::pi<double>() * (turns - std::floor(turns));
      // Seen from the body, the sun is opposite the body's own longitude.
      double lambda = body_longitude + glm::pi<double>();
      double eps = glm::radians(kObliquityJ2000Deg);
      glm::dvec3 dir_icrf(std::cos(lambda), std::sin(lambda) * std::cos(eps),
                          std::sin(lambda) * std::sin(eps));
      return glm::normalize(rotation.body_from_inertial(utc) * rotation.inertial_from_icrf() *
                            dir_icrf);
    }
    case SunEphemeris::Model::kNone:
      break;
  }
  throw InputError(
      "the body has no \"ephemeris\": its sun can only be given as elevation and azimuth");
}

HorizonAngles horizon_angles(const glm::dvec3& dir_body, double lat, double lon) {
  double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
  glm::dvec3 east(-so, co, 0.0), north(-sl * co, -sl * so, cl), up(cl * co, cl * so, sl);
  glm::dvec3 d = glm::normalize(dir_body);
  HorizonAngles a;
  a.elevation = std::asin(glm::clamp(glm::dot(d, up), -1.0, 1.0));
  a.azimuth = std::atan2(glm::dot(d, east), glm::dot(d, north));
  if (a.azimuth < 0) a.azimuth += 2.0 * glm::pi<double>();
  return a;
}

double sun_hour_angle(const glm::dvec3& sun_dir_body, double lon) {
  // The sun stands over the longitude atan2(y, x) of the body frame; the
  // hour angle is how far west of the place's meridian that is.
  double h =
      std::remainder(lon - std::atan2(sun_dir_body.y, sun_dir_body.x), 2.0 * glm::pi<double>());
  return h <= -glm::pi<double>() ? h + 2.0 * glm::pi<double>() : h;
}

double local_solar_hours(double hour_angle) {
  double hours = 12.0 + hour_angle * 12.0 / glm::pi<double>();
  return hours >= 24.0 ? hours - 24.0 : hours;
}

UtcSeconds utc_at_sun_hour_angle(const SunEphemeris& ephemeris, const BodyRotation& rotation,
                                 double lon, double hour_angle, UtcSeconds near) {
  if (!ephemeris.available()) return near;
  const double turn = 2.0 * glm::pi<double>();
  auto hour_angle_at = [&](UtcSeconds t) {
    return sun_hour_angle(sun_dir_body(ephemeris, rotation, t), lon);
  };
  // Newton's steps on the hour angle, which grows nearly evenly with time
  // (its rate is a turn over the solar day, taken from the ephemeris itself
  // over a minute): the first lands within seconds on every body here, and
  // wrapping the miss to (-pi, pi] keeps the answer within half a solar day.
  UtcSeconds t = near;
  for (int i = 0; i < 8; ++i) {
    double rate = std::remainder(hour_angle_at(t + 30.0) - hour_angle_at(t - 30.0), turn) / 60.0;
    if (rate == 0.0) break;
    double dt = -std::remainder(hour_angle_at(t) - hour_angle, turn) / rate;
    t += dt;
    if (std::abs(dt) < 0.1) break;
  }
  return t;
}

Daylight daylight(double sun_elevation, bool has_atmosphere) {
  if (sun_elevation >= 0.0) return Daylight::kDay;
  if (has_atmosphere && sun_elevation >= glm::radians(-12.0)) return Daylight::kTwilight;
  return Daylight::kNight;
}

const char* daylight_name(Daylight d) {
  switch (d) {
    case Daylight::kDay:
      return "day";
    case Daylight::kTwilight:
      return "twilight";
    case Daylight::kNight:
      return "night";
  }
  return "";
}

}  // namespace planet
