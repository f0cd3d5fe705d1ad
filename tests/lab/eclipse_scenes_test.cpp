// The eclipse scenes (lab/scene.h): where their cameras stand in the
// Moon's shadow, as the ephemeris puts it.
#include "lab/scene.h"
#include "sim/eclipse.h"
#include "sim/geodesy.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(EclipseScenesTest, TotalityStandsInTheUmbraAndThePartialPhaseKeepsATenthOfTheSun) {
  Scene total = find_scene("earth_eclipse_total");
  Scene partial = find_scene("earth_eclipse_partial");
  EXPECT_EQ(scene_sun_share(total, total.camera.pos_body), 0.0);
  EXPECT_NEAR(scene_sun_share(partial, partial.camera.pos_body), 0.1, 1e-6);
  // Without its Moon the same place has the whole sun.
  Scene clear = partial;
  clear.moon_radius = 0;
  EXPECT_EQ(scene_sun_share(clear, clear.camera.pos_body), 1.0);
  // NASA's greatest eclipse of 2024-04-08: 25.29 N, 104.14 W; the partial
  // scene due north of it, beyond the umbra's 99 km half width.
  Geodesy geodesy(scene_body(total).shape);
  Geodetic at = geodesy.geodetic_from_body(total.camera.pos_body);
  EXPECT_NEAR(glm::degrees(at.lat), 25.29, 0.05);
  EXPECT_NEAR(glm::degrees(at.lon), -104.14, 0.05);
  Geodetic north = geodesy.geodetic_from_body(partial.camera.pos_body);
  EXPECT_GT(glm::degrees(north.lat - at.lat), 1.0);
  EXPECT_NEAR(north.lon, at.lon, 1e-9);
}

TEST(EclipseScenesTest, FromOrbitTheUmbraLiesInTheMiddleOfTheView) {
  Scene orbit = find_scene("earth_eclipse_400km");
  Body body = scene_body(orbit);
  Geodesy geodesy(body.shape);
  Geodetic at = geodesy.geodetic_from_body(orbit.camera.pos_body);
  Geodetic centre = geodesy.geodetic_from_body(find_scene("earth_eclipse_total").camera.pos_body);
  EXPECT_NEAR(at.height, 400e3, 1.0);
  EXPECT_NEAR(glm::degrees(at.lat - centre.lat), 4.0, 1e-6);
  // The camera itself in the penumbra, the ground along the view's axis in
  // the umbra (the ellipsoid, walked to by bisection along the ray).
  double share = scene_sun_share(orbit, orbit.camera.pos_body);
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
  const glm::dvec3 axis = orbit.camera.forward_body();
  double lo = 0, hi = 2000e3;
  for (int i = 0; i < 60; ++i) {
    double mid = 0.5 * (lo + hi);
    (geodesy.geodetic_from_body(orbit.camera.pos_body + mid * axis).height > 0 ? lo : hi) = mid;
  }
  const glm::dvec3 ground = orbit.camera.pos_body + lo * axis;
  EXPECT_LT(lo, 1000e3);  // the axis meets the ground
  EXPECT_EQ(scene_sun_share(orbit, ground), 0.0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
