#pragma once
// Where the sun is, seen from a body at a UTC instant: a unit vector in the
// body-fixed frame. Earth and the Moon take the Sun and the Moon where ERFA
// puts them (sim/ephemeris.h: well under an arcsecond for the Sun, a few
// for the Moon), Mars the Mars24 algorithm, and other bodies a circular
// orbit in the ecliptic.
#include "sim/body_rotation.h"
#include "sim/utc_time.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace planet {

class JsonObject;

// The sun's apparent place from Earth, on the true equator and equinox of
// date (ERFA: the IAU 2006/2000A precession-nutation).
struct EarthSun {
  double right_ascension = 0;  // radians
  double declination = 0;      // radians
  double distance_au = 0;
};
EarthSun earth_sun(UtcSeconds utc);

struct SunEphemeris {
  // kEarth: the Earth's own frame (the ITRS, from ERFA), whatever the
  // body's "rotation"; kMoon: the sun from the Moon's true place, turned by
  // the body's rotation (the IAU model in the Moon's file).
  enum class Model { kNone, kEarth, kMoon, kMars24, kCircularOrbit };
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

// The other body of the Earth-Moon pair in this body's frame, metres from
// its centre: the Moon for the "earth" model, the Earth for the "moon"
// model, each where it really is at `utc`; none for other models.
std::optional<glm::dvec3> companion_pos_body(const SunEphemeris& ephemeris,
                                             const BodyRotation& rotation, UtcSeconds utc);
// Its name ("Moon", "Earth"), empty for the other models.
const char* companion_name(const SunEphemeris& ephemeris);

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
