#pragma once
// Where the sun is, seen from a body at a UTC instant: a unit vector in the
// body-fixed frame. Earth uses a standard low-precision solar position
// (Meeus 1998, "Astronomical Algorithms", ch. 25, about 0.01 deg over
// 1950-2050), Mars the Mars24 algorithm, and other bodies a circular orbit
// in the ecliptic.
#include "sim/body_rotation.h"
#include "sim/utc_time.h"

#include <glm/glm.hpp>

#include <string>

namespace planet {

class JsonObject;

// The sun's apparent place from Earth, on the true equator and equinox of
// date (Meeus ch. 25, "low accuracy").
struct EarthSun {
  double right_ascension = 0;  // radians
  double declination = 0;      // radians
  double distance_au = 0;
};
EarthSun earth_sun(UtcSeconds utc);

struct SunEphemeris {
  enum class Model { kNone, kEarth, kMars24, kCircularOrbit };
  Model model = Model::kNone;
  // kCircularOrbit: the body's heliocentric orbit, circular in the J2000
  // ecliptic.
  double orbit_radius_au = 0;
  double orbit_period = 0;     // seconds
  double longitude_j2000 = 0;  // heliocentric ecliptic longitude at J2000, radians

  bool available() const { return model != Model::kNone; }
  std::string name() const;
};

// Reads the "ephemeris" object of a body file.
SunEphemeris parse_ephemeris(JsonObject ephemeris);

// Unit vector toward the sun in the body-fixed frame; throws InputError for
// a body without an ephemeris.
glm::dvec3 sun_dir_body(const SunEphemeris& ephemeris, const BodyRotation& rotation,
                        UtcSeconds utc);

// Elevation above the local horizon and azimuth clockwise from north of a
// body-frame direction, seen from geodetic latitude/longitude (radians).
struct HorizonAngles {
  double elevation = 0, azimuth = 0;  // radians, azimuth in [0, 2 pi)
};
HorizonAngles horizon_angles(const glm::dvec3& dir_body, double lat, double lon);

// The sun's hour angle at a longitude (radians, east positive): 0 as the
// sun crosses the meridian, growing through the afternoon, in (-pi, pi].
double sun_hour_angle(const glm::dvec3& sun_dir_body, double lon);
// Local (apparent) solar time, hours from 0 to 24: 12 at the sun's transit.
double local_solar_hours(double hour_angle);
// The instant within half a solar day of `near` at which the sun's hour
// angle at `lon` is `hour_angle` (to a second of the body's solar day);
// `near` itself for a body without an ephemeris.
UtcSeconds utc_at_sun_hour_angle(const SunEphemeris& ephemeris, const BodyRotation& rotation,
                                 double lon, double hour_angle, UtcSeconds near);

// Whether it is day at a place: day while the sun's centre is above the
// horizon; under air, twilight down to 12 deg below it (nautical twilight's
// end, when the sky is dark enough for the bright stars), then night. An
// airless body has no twilight.
enum class Daylight { kDay, kTwilight, kNight };
Daylight daylight(double sun_elevation, bool has_atmosphere);
const char* daylight_name(Daylight daylight);

}  // namespace planet
