#include "sim/geodesy.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

const Ellipsoid kWgs84{6378137.0, 1.0 / 298.257223563};

// Round trip geodetic -> body -> geodetic; sub-millimetre in position.
void expect_round_trip(double lat_deg, double lon_deg, double height) {
  Geodesy geodesy(kWgs84);
  Geodetic g{glm::radians(lat_deg), glm::radians(lon_deg), height};
  glm::dvec3 p = geodesy.body_from_geodetic(g);
  Geodetic back = geodesy.geodetic_from_body(p);
  glm::dvec3 p2 = geodesy.body_from_geodetic(back);
  EXPECT_LT(glm::length(p2 - p), 1e-4) << lat_deg << " " << lon_deg << " " << height;
  EXPECT_NEAR(back.height, height, 1e-4);
  // Angles: 1e-4 m over 6.4e6 m is ~1.6e-11 rad.
  EXPECT_NEAR(back.lat, g.lat, 2e-11);
  if (std::abs(lat_deg) < 90.0) {
    double dlon = std::remainder(back.lon - g.lon, 2.0 * glm::pi<double>());
    EXPECT_NEAR(dlon, 0.0, 2e-11);
  }
}

TEST(GeodesyTest, RoundTripAtPolesEquatorAntimeridianAndAltitude) {
  for (double h : {0.0, 1.0, 8848.0, 1.0e6}) {
    expect_round_trip(90.0, 0.0, h);
    expect_round_trip(-90.0, 45.0, h);
    expect_round_trip(0.0, 0.0, h);
    expect_round_trip(0.0, 180.0, h);
    expect_round_trip(0.0, -180.0, h);
    expect_round_trip(0.0, 179.9999999, h);
    expect_round_trip(45.0, -179.9999999, h);
    expect_round_trip(-33.9, 18.4, h);
    expect_round_trip(89.9999, 12.0, h);
  }
}

TEST(GeodesyTest, PublishedPoints) {
  Geodesy geodesy(kWgs84);
  // On the equator at the prime meridian the point is (a, 0, 0); at the
  // pole it is (0, 0, b).
  glm::dvec3 p = geodesy.body_from_geodetic({0, 0, 0});
  EXPECT_NEAR(p.x, 6378137.0, 1e-6);
  glm::dvec3 pole = geodesy.body_from_geodetic({glm::half_pi<double>(), 0, 100.0});
  EXPECT_NEAR(pole.z, 6356752.314245 + 100.0, 1e-5);
  EXPECT_NEAR(glm::length(glm::dvec2(pole)), 0.0, 1e-6);
}

TEST(GeodesyTest, EnuFrameIsOrthonormalWithUpAlongNormal) {
  Geodesy geodesy(kWgs84);
  Geodetic g{glm::radians(46.5), glm::radians(8.0), 0};
  glm::dmat3 m = geodesy.body_from_enu(g);
  EXPECT_NEAR(glm::determinant(m), 1.0, 1e-12);
  // Up is the ellipsoid normal: a point 1 m up lies along it.
  glm::dvec3 p0 = geodesy.body_from_geodetic(g);
  glm::dvec3 p1 = geodesy.body_from_geodetic({g.lat, g.lon, 1.0});
  EXPECT_NEAR(glm::length(p1 - p0 - m[2]), 0.0, 1e-8);
}

TEST(GeodesyTest, CameraAttitudeFromHeadingPitchRoll) {
  // Heading 90 (east), pitch 0: camera forward (-z) is east (+x in ENU).
  glm::dquat q = enu_from_camera(glm::radians(90.0), 0.0, 0.0);
  glm::dvec3 forward = q * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(forward.x, 1.0, 1e-12);
  // Pitch up 30 degrees while facing north.
  q = enu_from_camera(0.0, glm::radians(30.0), 0.0);
  forward = q * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(forward.y, std::cos(glm::radians(30.0)), 1e-12);
  EXPECT_NEAR(forward.z, 0.5, 1e-12);
  // Roll right 90: the camera's up points east when facing north.
  q = enu_from_camera(0.0, 0.0, glm::radians(90.0));
  glm::dvec3 up = q * glm::dvec3(0, 1, 0);
  EXPECT_NEAR(up.x, 1.0, 1e-12);
}

// The HUD's heading and pitch (issue 62, point 6) read back the angles a
// camera was set with.
TEST(GeodesyTest, LookAnglesReadBackHeadingPitchAndRoll) {
  for (double heading : {0.0, 45.0, 90.0, 181.0, 359.0}) {
    for (double pitch : {-89.0, -30.0, 0.0, 12.5, 89.0}) {
      for (double roll : {-120.0, 0.0, 30.0, 179.0}) {
        LookAngles a = look_angles(
            enu_from_camera(glm::radians(heading), glm::radians(pitch), glm::radians(roll)));
        EXPECT_NEAR(glm::degrees(a.heading), heading, 1e-9)
            << heading << " " << pitch << " " << roll;
        EXPECT_NEAR(glm::degrees(a.pitch), pitch, 1e-9) << heading << " " << pitch << " " << roll;
        EXPECT_NEAR(glm::degrees(a.roll), roll, 1e-9) << heading << " " << pitch << " " << roll;
      }
    }
  }
  // Straight down, the heading is the camera top's.
  LookAngles down = look_angles(enu_from_camera(glm::radians(90.0), glm::radians(-90.0), 0.0));
  EXPECT_NEAR(glm::degrees(down.heading), 90.0, 1e-6);
  EXPECT_NEAR(glm::degrees(down.pitch), -90.0, 1e-6);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
