#include "sim/sun_ephemeris.h"

#include "core/error.h"
#include "core/json_reader.h"
#include "sim/ephemeris.h"
#include "sim/mars24.h"

#include <erfa.h>

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace planet {

namespace {

constexpr double kSecondsPerDay = 86400.0;
// Mean obliquity of the ecliptic at J2000 (Meeus eq. 22.2 at T = 0).
constexpr double kObliquityJ2000Deg = 23.4392911;

}  // namespace

EarthSun earth_sun(UtcSeconds utc) {
  // GCRS to the true equator and equinox of date.
  ErfaDates d = erfa_dates(utc);
  double npb[3][3];
  eraPnm06a(d.tt1, d.tt2, npb);
  glm::dvec3 gcrs = sun_pos_gcrs(utc), p;
  for (int r = 0; r < 3; ++r) p[r] = npb[r][0] * gcrs.x + npb[r][1] * gcrs.y + npb[r][2] * gcrs.z;
  EarthSun sun;
  sun.right_ascension = std::atan2(p.y, p.x);
  sun.declination = std::asin(p.z / glm::length(p));
  sun.distance_au = glm::length(p) / kAuMetres;
  return sun;
}

std::string SunEphemeris::name() const {
  switch (model) {
    case Model::kEarth:
      return "earth";
    case Model::kMoon:
      return "moon";
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
  } else if (model == "moon") {
    e.model = SunEphemeris::Model::kMoon;
  } else if (model == "mars24") {
    e.model = SunEphemeris::Model::kMars24;
  } else if (model == "circular_orbit") {
    e.model = SunEphemeris::Model::kCircularOrbit;
    e.orbit_radius_au = ephemeris.number("orbit_radius_au", 1e-3, 1e4);
    e.orbit_period = ephemeris.number("orbit_period_days", 1e-3, 1e8) * kSecondsPerDay;
    e.longitude_j2000 = glm::radians(ephemeris.number("longitude_j2000_deg", -360.0, 360.0));
  } else {
    ephemeris.fail(
        "model",
        fmt::format("'{}' is not a known model (earth, moon, mars24, circular_orbit)", model));
  }
  ephemeris.finish();
  return e;
}

glm::dvec3 sun_dir_body(const SunEphemeris& ephemeris, const BodyRotation& rotation,
                        UtcSeconds utc) {
  switch (ephemeris.model) {
    case SunEphemeris::Model::kEarth:
      // The Earth's true frame, not the body file's uniform spin about a
      // fixed pole: that one drifts from the sky by the precession since
      // J2000 (0.3 deg by 2024), which the sun's place must not.
      return glm::normalize(itrs_from_gcrs(utc) * sun_pos_gcrs(utc));
    case SunEphemeris::Model::kMoon: {
      // The GCRS's axes are the ICRF's.
      glm::dvec3 dir_icrf = glm::normalize(sun_pos_gcrs(utc) - moon_pos_gcrs(utc));
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

std::optional<glm::dvec3> companion_pos_body(const SunEphemeris& ephemeris,
                                             const BodyRotation& rotation, UtcSeconds utc) {
  if (ephemeris.model == SunEphemeris::Model::kEarth) {
    return itrs_from_gcrs(utc) * moon_pos_gcrs(utc);
  }
  if (ephemeris.model == SunEphemeris::Model::kMoon) {
    return rotation.body_from_inertial(utc) * rotation.inertial_from_icrf() * -moon_pos_gcrs(utc);
  }
  return std::nullopt;
}

const char* companion_name(const SunEphemeris& ephemeris) {
  if (ephemeris.model == SunEphemeris::Model::kEarth) return "Moon";
  if (ephemeris.model == SunEphemeris::Model::kMoon) return "Earth";
  return "";
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
