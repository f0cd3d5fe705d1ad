// The Sun, the Moon and the Earth's orientation from ERFA against published
// worked examples, and the bodies' frames built on them.
#include "sim/ephemeris.h"
#include "sim/body.h"
#include "sim/geodesy.h"
#include "sim/sun_ephemeris.h"

#include <erfa.h>
#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kArcSecondDeg = 1.0 / 3600.0;

// Right ascension and declination on the true equator and equinox of date,
// degrees, of a GCRS vector.
glm::dvec2 ra_dec_of_date(const glm::dvec3& gcrs, UtcSeconds utc) {
  ErfaDates d = erfa_dates(utc);
  double npb[3][3];
  eraPnm06a(d.tt1, d.tt2, npb);
  glm::dvec3 p;
  for (int r = 0; r < 3; ++r) p[r] = npb[r][0] * gcrs.x + npb[r][1] * gcrs.y + npb[r][2] * gcrs.z;
  double ra = glm::degrees(std::atan2(p.y, p.x));
  return {ra < 0 ? ra + 360.0 : ra, glm::degrees(std::asin(p.z / glm::length(p)))};
}

TEST(EphemerisTest, DeltaTFollowsTheObservedValues) {
  // TT - UT1 as the IERS observed it: 68.59 s on 2017-01-01, 69.18 s on
  // 2024-01-01; in between, interpolated.
  EXPECT_NEAR(delta_t(parse_utc("2017-01-01", "t")), 68.59, 0.02);
  EXPECT_NEAR(delta_t(parse_utc("2017-08-21", "t")), 68.8, 0.1);
  EXPECT_NEAR(delta_t(parse_utc("2024-04-08", "t")), 69.2, 0.1);
  // The ends of the table join the formulas beyond them.
  double before = delta_t(parse_utc("1989-12-31T12:00Z", "t"));
  double after = delta_t(parse_utc("1990-01-01T12:00Z", "t"));
  EXPECT_NEAR(before, after, 0.1);
  EXPECT_NEAR(delta_t(parse_utc("2026-01-01T00:00Z", "t") - 60.0),
              delta_t(parse_utc("2026-01-01T00:00Z", "t") + 60.0), 0.01);
  // Espenak and Meeus's 1961-1986 polynomial: 45.45 s at 1975.0.
  EXPECT_NEAR(delta_t(parse_utc("1975-01-01", "t")), 45.45, 0.05);
}

TEST(EphemerisTest, MoonMatchesMeeusExample47a) {
  // Meeus 1998, example 47.a: 1992 April 12, 0h TD: apparent right
  // ascension 134.688470 deg, declination 13.768368 deg, distance 368409.7
  // km (from the centres). Moon98 is that chapter's series; the light's 1.3
  // s (0.7 arcsec), which Meeus leaves out, and the nutation models make up
  // the difference.
  UtcSeconds td = parse_utc("1992-04-12", "t");
  UtcSeconds utc = td - tt_minus_utc(td);
  glm::dvec3 moon = moon_pos_gcrs(utc);
  glm::dvec2 radec = ra_dec_of_date(moon, utc);
  EXPECT_NEAR(radec.x, 134.688470, 2.0 * kArcSecondDeg);
  EXPECT_NEAR(radec.y, 13.768368, 2.0 * kArcSecondDeg);
  EXPECT_NEAR(glm::length(moon) / 1000.0, 368409.7, 2.0);
}

TEST(EphemerisTest, EarthTurnsWithApparentSiderealTime) {
  // Meeus 1998, example 12.a: apparent sidereal time at Greenwich on 1987
  // April 10, 0h UT, is 13h10m46.1351s: the true equinox of date stands at
  // that hour angle, i.e. at longitude -GAST in the Earth's frame. UTC is
  // 0.3 s behind UT1 then (delta_t against the leap seconds): 4.5 arcsec.
  UtcSeconds utc = parse_utc("1987-04-10", "t");
  ErfaDates d = erfa_dates(utc);
  double npb[3][3];
  eraPnm06a(d.tt1, d.tt2, npb);
  glm::dvec3 equinox_gcrs(npb[0][0], npb[0][1], npb[0][2]);  // first row: x of date
  glm::dvec3 equinox_itrs = itrs_from_gcrs(utc) * equinox_gcrs;
  double gast_deg = -glm::degrees(std::atan2(equinox_itrs.y, equinox_itrs.x));
  double expected = (13 + 10 / 60.0 + 46.1351 / 3600.0) * 15.0;
  EXPECT_NEAR(std::remainder(gast_deg - expected, 360.0), 0.0, 8.0 * kArcSecondDeg);
}

TEST(EphemerisTest, AtGreatestEclipseTheMoonCoversTheSunFromThePoint) {
  // NASA: greatest eclipse of 2017-08-21 at 18:25:30 UT, 37.0 N 87.7 W. Seen
  // from there the two centres stand within a small part of the Moon's
  // 16-arcminute radius (the low-precision Sun alone was 0.47' off).
  Body earth = load_body(find_body_file("earth"));
  UtcSeconds utc = parse_utc("2017-08-21T18:25:30Z", "t");
  Geodetic place{glm::radians(36.97), glm::radians(-87.67), 0.0};
  glm::dvec3 at = Geodesy(earth.shape).body_from_geodetic(place);
  glm::dvec3 sun = sun_dir_body(earth.ephemeris, earth.rotation, utc);
  glm::dvec3 moon = glm::normalize(*companion_pos_body(earth.ephemeris, earth.rotation, utc) - at);
  EXPECT_LT(glm::degrees(std::acos(glm::dot(sun, moon))), 1.0 / 60.0);
}

TEST(EphemerisTest, FromTheMoonTheSunAndTheEarthLineUpInAnEclipse) {
  // 2024-04-08, greatest eclipse: from the Moon the Earth stands opposite
  // the Sun, off by the axis's distance from the Earth's centre (gamma
  // 0.343 Earth radii) over the Moon's 359 800 km: 0.35 deg.
  Body moon = load_body(find_body_file("moon"));
  EXPECT_EQ(moon.ephemeris.name(), "moon");
  UtcSeconds utc = parse_utc("2024-04-08T18:17:15Z", "t");
  glm::dvec3 sun = sun_dir_body(moon.ephemeris, moon.rotation, utc);
  glm::dvec3 earth = *companion_pos_body(moon.ephemeris, moon.rotation, utc);
  double off_deg = glm::degrees(std::acos(glm::dot(-sun, glm::normalize(earth))));
  EXPECT_NEAR(off_deg, glm::degrees(0.343 * 6378.137 / 359800.0), 0.02);
  EXPECT_NEAR(glm::length(earth) / 1000.0, 359800.0, 300.0);
  // Seen from the Moon, the sun is not the Earth's: 0.15 deg apart at most.
  glm::dvec3 sun_from_earth = glm::normalize(sun_pos_gcrs(utc));
  glm::dvec3 sun_from_moon = glm::normalize(sun_pos_gcrs(utc) - moon_pos_gcrs(utc));
  double parallax = glm::degrees(std::acos(glm::dot(sun_from_earth, sun_from_moon)));
  EXPECT_GT(parallax, 0.0);
  EXPECT_LT(parallax, 0.15);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
