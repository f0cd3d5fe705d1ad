// The shipped star catalogue and where its stars stand in the sky: against
// the textbook hour-angle formulae with Meeus's sidereal time, which share
// nothing with the body frame's rotation.
#include "sim/star_catalogue.h"

#include "core/error.h"
#include "sim/body.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

const Star& star_numbered(int hr) {
  const auto& stars = bright_stars();
  auto it = std::find_if(stars.begin(), stars.end(), [&](const Star& s) { return s.hr == hr; });
  EXPECT_NE(it, stars.end()) << "HR " << hr;
  return *it;
}

TEST(StarCatalogueTest, HoldsTheNakedEyeStarsBrightestFirst) {
  const auto& stars = bright_stars();
  // The Bright Star Catalogue has 5080 entries to V = 6.0.
  EXPECT_EQ(stars.size(), 5080u);
  EXPECT_EQ(stars.front().hr, 2491);  // Sirius
  EXPECT_DOUBLE_EQ(stars.front().magnitude, -1.46);
  for (size_t i = 1; i < stars.size(); ++i) {
    ASSERT_LE(stars[i - 1].magnitude, stars[i].magnitude) << i;
    ASSERT_LE(stars[i].magnitude, 6.0);
    ASSERT_NEAR(glm::length(stars[i].dir_icrf), 1.0, 1e-12);
  }
  // Polaris: RA 2h31m49s, Dec +89 deg 15' 51" (J2000).
  const Star& polaris = star_numbered(424);
  EXPECT_NEAR(glm::degrees(std::asin(polaris.dir_icrf.z)), 89.264, 1e-3);
  EXPECT_NEAR(polaris.magnitude, 2.02, 1e-9);
}

TEST(StarCatalogueTest, MagnitudesScaleTheSunsIrradiance) {
  EXPECT_NEAR(star_irradiance_per_sun(-26.74), 1.0, 1e-12);
  // Five magnitudes are a factor of 100.
  EXPECT_NEAR(star_irradiance_per_sun(1.0) / star_irradiance_per_sun(6.0), 100.0, 1e-9);
  // Vega (0.03): about 2.0e-11 of the sun.
  EXPECT_NEAR(star_irradiance_per_sun(0.03) / 2.0e-11, 1.0, 0.03);
}

// Elevation and azimuth (clockwise from north), degrees, of a star at
// (ra, dec) radians from geodetic (lat, lon) radians at `utc`: Meeus 1998,
// eq. 12.4 for the mean sidereal time and eq. 13.5-13.6 for the horizon.
std::pair<double, double> textbook_alt_az(double ra, double dec, double lat, double lon,
                                          UtcSeconds utc) {
  const double d = julian_date(utc) - 2451545.0;
  const double gmst = glm::radians(280.46061837 + 360.98564736629 * d);
  const double h = gmst + lon - ra;
  const double alt =
      std::asin(std::sin(lat) * std::sin(dec) + std::cos(lat) * std::cos(dec) * std::cos(h));
  // Meeus measures azimuth from the south, westward.
  const double az_south =
      std::atan2(std::sin(h), std::cos(h) * std::sin(lat) - std::tan(dec) * std::cos(lat));
  return {glm::degrees(alt), std::fmod(glm::degrees(az_south) + 180.0 + 360.0, 360.0)};
}

TEST(StarCatalogueTest, StarsStandWhereTheHourAngleFormulaePutThem) {
  Body earth = load_body(find_body_file("earth"));
  const double lat = glm::radians(46.55), lon = glm::radians(7.98);
  const UtcSeconds utc = parse_utc("2026-01-15T21:00:00Z", "test");
  const glm::dmat3 turn = body_from_icrf(earth, utc);
  int above = 0;
  for (int hr : {2491, 2061, 1713, 424, 7001, 5340, 4730}) {  // Sirius ... Acrux
    const Star& s = star_numbered(hr);
    const double dec = std::asin(s.dir_icrf.z), ra = std::atan2(s.dir_icrf.y, s.dir_icrf.x);
    auto [alt, az] = textbook_alt_az(ra, dec, lat, lon, utc);
    HorizonAngles ours = horizon_angles(turn * s.dir_icrf, lat, lon);
    EXPECT_NEAR(glm::degrees(ours.elevation), alt, 0.01) << "HR " << hr;
    // Azimuth is undefined at the zenith; none of these is near it.
    EXPECT_NEAR(std::remainder(glm::degrees(ours.azimuth) - az, 360.0), 0.0, 0.01) << "HR " << hr;
    above += alt > 0;
  }
  // A January evening in the Alps: Sirius, Betelgeuse, Rigel and Polaris
  // are up; Vega, near its lower culmination, is 5 deg under the northern
  // horizon, and Arcturus and Acrux are down too.
  EXPECT_EQ(above, 4);
  // Polaris stands within its 0.74 deg from the pole of the latitude, due
  // north.
  HorizonAngles polaris = horizon_angles(turn * star_numbered(424).dir_icrf, lat, lon);
  EXPECT_NEAR(glm::degrees(polaris.elevation), 46.55, 0.75);
  EXPECT_NEAR(std::remainder(glm::degrees(polaris.azimuth), 360.0), 0.0, 1.1);
}

TEST(StarCatalogueTest, ABodyWithoutSpinKeepsTheIcrfAxes) {
  Body still;
  glm::dmat3 turn = body_from_icrf(still, 1e9);
  EXPECT_EQ(turn, glm::dmat3(1.0));
}

TEST(StarCatalogueTest, AMalformedCatalogueNamesItsFileAndLine) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("planet_star_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto expect_refused = [&](const std::string& text, const std::string& needle) {
    const auto file = dir / "stars.csv";
    std::ofstream(file) << text;
    try {
      read_star_catalogue(file);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const std::string header = "# a comment\nhr,ra_hours,dec_deg,vmag\n";
  expect_refused(header + "1,6.75,-16.7,-1.46\n2,24.0,0,1\n", "stars.csv:4:");
  expect_refused(header + "1,6.75,-96.7,1\n", "stars.csv:3:");
  expect_refused(header + "1,6.75,-16.7\n", "stars.csv:3:");
  expect_refused(header + "1,6.75,-16.7,1,9\n", "stars.csv:3:");
  expect_refused(header + "1,nan,-16.7,1\n", "stars.csv:3:");
  expect_refused("ra,dec\n1,2\n", "stars.csv:1: expected the header");
  expect_refused(header, "no stars");
  expect_refused("", "no stars");
  try {
    read_star_catalogue(dir / "missing.csv");
    ADD_FAILURE() << "read a missing file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.csv"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
