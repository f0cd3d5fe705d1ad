// Geodesics on the WGS84 ellipsoid against closed forms and published values.
#include "sim/surface_line.h"
#include "sim/body.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(SurfaceLineTest, EquatorMeridianAndRoundTrip) {
  Body earth = load_body(find_body_file("earth"));
  Geodesics geodesics(earth.shape);
  // Along the equator a short arc is a circle of radius a.
  SurfaceLine east = geodesics.between({0, 0, 0}, {0, glm::radians(10.0), 0});
  EXPECT_NEAR(east.distance, 6378137.0 * glm::radians(10.0), 1e-6);
  EXPECT_NEAR(glm::degrees(east.start_heading), 90.0, 1e-9);
  // The WGS84 quarter meridian is 10 001 965.729 m (NIMA TR8350.2, 2000).
  SurfaceLine north = geodesics.between({0, 0, 0}, {glm::radians(90.0), 0, 0});
  EXPECT_NEAR(north.distance, 10001965.729, 1e-3);
  EXPECT_NEAR(glm::degrees(north.start_heading), 0.0, 1e-9);
  // Travelling a line lands where the line ends.
  Geodetic paris{glm::radians(48.85), glm::radians(2.35), 100.0};
  Geodetic tokyo{glm::radians(35.68), glm::radians(139.69), 0.0};
  SurfaceLine line = geodesics.between(paris, tokyo);
  Geodetic there = geodesics.travel(paris, line.start_heading, line.distance);
  EXPECT_NEAR(glm::degrees(there.lat), 35.68, 1e-9);
  EXPECT_NEAR(glm::degrees(there.lon), 139.69, 1e-9);
  EXPECT_EQ(there.height, 100.0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
