// Earth's sun against independent references: Meeus's worked examples and
// a second, independently fitted algorithm (PSA, Blanco-Muriel et al. 2001).
#include "sim/sun_ephemeris.h"
#include "core/error.h"
#include "sim/body.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kArcMinuteDeg = 1.0 / 60.0;

double wrap_deg(double d) { return std::remainder(d, 360.0); }

// The PSA algorithm: Blanco-Muriel, Alarcon-Padilla, Lopez-Moratalla and
// Lara-Coira (2001), "Computing the solar vector", Solar Energy 70(5),
// 431-441: its own fit of the sun's ecliptic longitude and of sidereal
// time, quoted at 0.5 arc-minute over 1999-2015. Returns the topocentric
// elevation and the azimuth clockwise from north, degrees.
HorizonAngles psa(int year, int month, int day, double hours, double lat_deg, double lon_deg) {
  double pi = glm::pi<double>();
  long a = (month - 14) / 12;
  double jd = double((1461 * (year + 4800 + a)) / 4 + (367 * (month - 2 - 12 * a)) / 12 -
                     (3 * ((year + 4900 + a) / 100)) / 4 + day) -
              32075 - 0.5 + hours / 24.0;
  double n = jd - 2451545.0;
  double omega = 2.1429 - 0.0010394594 * n;
  double mean_lon = 4.8950630 + 0.017202791698 * n;
  double mean_anom = 6.2400600 + 0.0172019699 * n;
  double ecl_lon = mean_lon + 0.03341607 * std::sin(mean_anom) +
                   0.00034894 * std::sin(2 * mean_anom) - 0.0001134 - 0.0000203 * std::sin(omega);
  double obliquity = 0.4090928 - 6.2140e-9 * n + 0.0000396 * std::cos(omega);
  double ra = std::atan2(std::cos(obliquity) * std::sin(ecl_lon), std::cos(ecl_lon));
  if (ra < 0) ra += 2 * pi;
  double dec = std::asin(std::sin(obliquity) * std::sin(ecl_lon));
  double gmst = 6.6974243242 + 0.0657098283 * n + hours;
  double lmst = glm::radians(gmst * 15.0 + lon_deg);
  double ha = lmst - ra;
  double lat = glm::radians(lat_deg);
  double zenith =
      std::acos(std::cos(lat) * std::cos(ha) * std::cos(dec) + std::sin(dec) * std::sin(lat));
  double azimuth =
      std::atan2(-std::sin(ha), std::tan(dec) * std::cos(lat) - std::sin(lat) * std::cos(ha));
  if (azimuth < 0) azimuth += 2 * pi;
  zenith += (6371.01 / 149597890.0) * std::sin(zenith);  // parallax
  return {glm::radians(90.0) - zenith, azimuth};
}

TEST(SunEphemerisTest, MatchesMeeusHighAccuracyExample25b) {
  // Meeus 1998, example 25.b (the full VSOP87, FK5): 1992 October 13.0 TD,
  // apparent right ascension 13h13m30.749s, declination -7 deg 47' 01.74",
  // R = 0.99760775 AU. Meeus's low-accuracy series, which Earth's sun once
  // came from, is 0.65 s (9.8 arcsec) off in right ascension here.
  UtcSeconds td = parse_utc("1992-10-13T00:00:00Z", "test");
  EarthSun sun = earth_sun(td - tt_minus_utc(td));
  double ra_deg = glm::degrees(sun.right_ascension);
  if (ra_deg < 0) ra_deg += 360.0;
  constexpr double kArcSecondDeg = 1.0 / 3600.0;
  EXPECT_NEAR(ra_deg, (13 + 13 / 60.0 + 30.749 / 3600.0) * 15.0, 0.5 * kArcSecondDeg);
  EXPECT_NEAR(glm::degrees(sun.declination), -(7 + 47 / 60.0 + 1.74 / 3600.0), 0.5 * kArcSecondDeg);
  // Ours is 7.9e-7 AU (118 km, 0.0002 of the Sun's radius) further.
  EXPECT_NEAR(sun.distance_au, 0.99760775, 1e-6);
}

TEST(SunEphemerisTest, EarthTurnsWithGreenwichSiderealTime) {
  // Meeus 1998, example 12.a: mean sidereal time at Greenwich on 1987 April
  // 10, 0h UT, is 13h10m46.3668s. The body frame's W is that less 90 deg.
  Body earth = load_body(find_body_file("earth"));
  double w = glm::degrees(earth.rotation.angle(parse_utc("1987-04-10T00:00:00Z", "test")));
  double gmst = (13 + 10 / 60.0 + 46.3668 / 3600.0) * 15.0;
  EXPECT_NEAR(wrap_deg(w + 90.0 - gmst), 0.0, 1.0 / 3600.0);
}

TEST(SunEphemerisTest, EarthAgreesWithIndependentAlgorithmWithinOneArcMinute) {
  Body earth = load_body(find_body_file("earth"));
  struct Case {
    int y, m, d;
    double hours, lat, lon;
  };
  // Dates across the PSA's validity, places on all sides of the globe, the
  // sun high, low, east, west, and under the horizon.
  const Case cases[] = {
      {1999, 3, 21, 12.0, 48.85, 2.35},     {2003, 6, 21, 6.5, 37.77, -122.42},
      {2006, 12, 22, 3.25, -33.87, 151.21}, {2010, 9, 23, 18.0, 64.15, -21.94},
      {2012, 1, 15, 9.75, 0.0, 36.8},       {2014, 7, 4, 21.5, -54.8, -68.3},
      {2015, 11, 30, 15.0, 78.2, 15.6},     {2008, 2, 29, 0.0, 35.68, 139.69},
  };
  for (const Case& c : cases) {
    UtcSeconds utc =
        parse_utc(fmt::format("{:04d}-{:02d}-{:02d}", c.y, c.m, c.d), "test") + c.hours * 3600.0;
    HorizonAngles ours = horizon_angles(sun_dir_body(earth.ephemeris, earth.rotation, utc),
                                        glm::radians(c.lat), glm::radians(c.lon));
    HorizonAngles ref = psa(c.y, c.m, c.d, c.hours, c.lat, c.lon);
    SCOPED_TRACE(::testing::Message() << c.y << "-" << c.m << "-" << c.d << " " << c.hours
                                      << " h at " << c.lat << ", " << c.lon);
    EXPECT_NEAR(glm::degrees(ours.elevation), glm::degrees(ref.elevation), kArcMinuteDeg);
    // Azimuth error shrinks by cos(elevation) on the sky; compare it so.
    EXPECT_NEAR(wrap_deg(glm::degrees(ours.azimuth - ref.azimuth)) * std::cos(ref.elevation), 0.0,
                kArcMinuteDeg);
  }
}

TEST(SunEphemerisTest, ParisAtMidsummerNoonIsHighInTheSouth) {
  Body earth = load_body(find_body_file("earth"));
  UtcSeconds utc = parse_utc("2026-06-21T12:00:00Z", "test");
  HorizonAngles a = horizon_angles(sun_dir_body(earth.ephemeris, earth.rotation, utc),
                                   glm::radians(48.85), glm::radians(2.35));
  // 90 - 48.85 + 23.44 at true noon, a few minutes before 12:00 UTC here.
  EXPECT_NEAR(glm::degrees(a.elevation), 64.59, 0.1);
  EXPECT_GT(glm::degrees(a.azimuth), 180.0);
  EXPECT_LT(glm::degrees(a.azimuth), 190.0);
}

TEST(SunEphemerisTest, AsteroidSunTurnsWithItsSpinAndCreepsWithItsOrbit) {
  Body rock = load_body(find_body_file("asteroid"));
  UtcSeconds t0 = parse_utc("2026-06-21T00:00:00Z", "test");
  double period = rock.rotation.sidereal_period;
  glm::dvec3 s0 = sun_dir_body(rock.ephemeris, rock.rotation, t0);
  // Half a turn later the sun has swung to the other side of the pole axis.
  glm::dvec3 s_half = sun_dir_body(rock.ephemeris, rock.rotation, t0 + 0.5 * period);
  // Meanwhile the orbit has carried the sun 2 pi (P/2) / P_orbit across the
  // sky, which bounds how far its height over the equator can move.
  double orbit_drift = glm::pi<double>() * period / rock.ephemeris.orbit_period;
  EXPECT_NEAR(s_half.z, s0.z, orbit_drift + 1e-4);
  EXPECT_NEAR(s_half.x, -s0.x, 1e-2);
  EXPECT_NEAR(s_half.y, -s0.y, 1e-2);
  // After a whole sidereal turn only the orbit has moved it: 360 deg times
  // the turn over the orbital period, projected on the sky.
  glm::dvec3 s1 = sun_dir_body(rock.ephemeris, rock.rotation, t0 + period);
  double moved = glm::degrees(std::acos(std::min(1.0, glm::dot(s0, s1))));
  double orbital = 360.0 * period / rock.ephemeris.orbit_period;
  EXPECT_GT(moved, 0.3 * orbital);
  EXPECT_LT(moved, 1.01 * orbital);
}

TEST(SunEphemerisTest, BadRotationAndEphemerisKeysNameTheField) {
  auto file = std::filesystem::temp_directory_path() /
              ("planet_body_" + std::to_string(::getpid()) + ".json");
  auto expect_error = [&](const std::string& keys, const std::string& fragment) {
    std::ofstream(file)
        << R"({"name": "B", "shape": {"type": "ellipsoid", "equatorial_radius_m": 1000},)" << keys
        << "}";
    try {
      load_body(file);
      ADD_FAILURE() << "no error for " << keys;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  const std::string spin =
      R"("rotation": {"pole_ra_deg": 0, "pole_dec_deg": 90, "prime_meridian_j2000_deg": 0, )";
  expect_error(R"("ephemeris": {"model": "earth"})", "ephemeris");
  expect_error(spin + R"("sidereal_period_s": 0}, "ephemeris": {"model": "earth"})",
               "rotation.sidereal_period_s");
  expect_error(spin + R"("sidereal_period_s": 3600}, "ephemeris": {"model": "vsop87"})",
               "ephemeris.model");
  expect_error(R"("rotation": {"pole_ra_deg": 0, "pole_dec_deg": 91, "prime_meridian_j2000_deg": 0,
                 "sidereal_period_s": 3600})",
               "rotation.pole_dec_deg");
  std::filesystem::remove(file);
}

TEST(SunEphemerisTest, BodyWithoutEphemerisIsAnInputError) {
  SunEphemeris none;
  EXPECT_THROW(sun_dir_body(none, BodyRotation{}, 0.0), InputError);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
