// Mars24 against the worked example A of NASA GISS's "Mars24 Algorithm and
// Worked Examples" (2000 January 6, 00:00:00 UTC, at longitude 0).
#include "sim/mars24.h"
#include "sim/body.h"
#include "sim/sun_ephemeris.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(Mars24Test, MatchesPublishedWorkedExample) {
  UtcSeconds utc = parse_utc("2000-01-06T00:00:00Z", "test");
  // TT - UTC = 64.184 s on that date.
  EXPECT_DOUBLE_EQ(tt_minus_utc(utc), 64.184);
  MarsSun sun = mars_sun(utc);
  // The example prints five decimals; allow one unit in the last place.
  EXPECT_NEAR(glm::degrees(sun.ls), 277.18758, 1e-5);                   // B-5
  EXPECT_NEAR(glm::degrees(sun.equation_of_time), -5.18774, 1e-5);      // C-1
  EXPECT_NEAR(sun.mean_solar_time_h, 23.99425, 1e-5);                   // C-2
  EXPECT_NEAR(mars_local_true_solar_time_h(sun, 0.0), 23.64840, 1e-5);  // C-4
  // C-5: subsolar longitude 174.72600 deg west.
  EXPECT_NEAR(-glm::degrees(sun.subsolar_lon_east), 174.72600, 1e-5);
  // D-1 applied to the published Ls: asin(0.42565 sin Ls) + 0.25 deg sin Ls.
  double ls = glm::radians(277.18758);
  double dec = glm::degrees(std::asin(0.42565 * std::sin(ls))) + 0.25 * std::sin(ls);
  EXPECT_NEAR(glm::degrees(sun.subsolar_lat), dec, 1e-5);
}

TEST(Mars24Test, SunDirectionPointsAtTheSubsolarPoint) {
  Body mars = load_body(find_body_file("mars"));
  UtcSeconds utc = parse_utc("2000-01-06T00:00:00Z", "test");
  MarsSun sun = mars_sun(utc);
  glm::dvec3 dir = sun_dir_body(mars.ephemeris, mars.rotation, utc);
  HorizonAngles overhead = horizon_angles(dir, sun.subsolar_lat, sun.subsolar_lon_east);
  EXPECT_NEAR(glm::degrees(overhead.elevation), 90.0, 1e-6);
  // At the prime meridian it is 23:39 local true solar time: night.
  HorizonAngles origin = horizon_angles(dir, 0.0, 0.0);
  EXPECT_LT(origin.elevation, glm::radians(-60.0));
}

// At the solstices the subsolar latitude is the planetographic obliquity
// term of D-1: +-25.441 deg, as an independent implementation of the same
// algorithm (C. Lee's marstime, its solar_declination tests) gives it.
TEST(Mars24Test, SubsolarLatitudeAtTheSolstices) {
  for (double target_deg : {90.0, 270.0}) {
    // Bisect for the instant Ls crosses the target within one Martian year
    // from 2020, where Ls grows monotonically between the bounds found by
    // stepping a day at a time.
    UtcSeconds t = parse_utc("2020-01-01T00:00:00Z", "test");
    auto offset = [&](UtcSeconds u) {
      return std::remainder(mars_sun(u).ls - glm::radians(target_deg), 2 * glm::pi<double>());
    };
    while (!(offset(t) < 0.0 && offset(t + 86400.0) >= 0.0)) t += 86400.0;
    UtcSeconds lo = t, hi = t + 86400.0;
    for (int i = 0; i < 50; ++i) {
      UtcSeconds mid = 0.5 * (lo + hi);
      (offset(mid) < 0.0 ? lo : hi) = mid;
    }
    double expected = target_deg == 90.0 ? 25.441 : -25.441;
    EXPECT_NEAR(glm::degrees(mars_sun(lo).subsolar_lat), expected, 1e-3) << target_deg;
  }
}

TEST(Mars24Test, SolarLongitudeAdvancesOneMartianYearIn687Days) {
  UtcSeconds t0 = parse_utc("2020-01-01T00:00:00Z", "test");
  double ls0 = mars_sun(t0).ls;
  double ls1 = mars_sun(t0 + 686.97 * 86400.0).ls;
  EXPECT_NEAR(std::remainder(ls1 - ls0, 2 * glm::pi<double>()), 0.0, glm::radians(0.1));
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
