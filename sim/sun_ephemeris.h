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

}  // namespace planet
