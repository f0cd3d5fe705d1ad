// Free flight and orbit flight as a pilot meets them, and the fixed step.
#include "sim/free_flight.h"
#include "sim/orbit_flight.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(FlightControllerTest, FixedStepCarriesTheRemainder) {
  FixedStep step(1.0 / 120.0);
  int total = 0;
  for (int i = 0; i < 100; ++i) total += step.advance(1.0 / 60.0 + 1e-4);
  // 100 frames of 1/60 s and a little: 200 steps plus the carried 1.2 steps.
  EXPECT_EQ(total, 201);
  // A long stall runs at most the cap, and drops the rest.
  EXPECT_EQ(step.advance(10.0, 8), 8);
  EXPECT_EQ(step.advance(0.0), 0);
}

TEST(FlightControllerTest, SpeedScalesWithHeight) {
  Body earth = load_body(find_body_file("earth"));
  Geodesy geodesy(earth.shape);
  // Centimetres per second near the ground, capped at 5000 km/s far out.
  for (double h : {0.6, 1.0, 1000.0, 1.0e6, 1.0e9}) {
    FreeFlight flight(earth, Geodetic{0.3, 0.2, h}, 0.0);
    FlightInput in;
    in.move = {0, 0, 1};  // forward, level
    flight.step(0.001, 0.0, in);
    double expected = std::clamp(0.2 * h, FreeFlight::kMinSpeed, FreeFlight::kMaxSpeed);
    EXPECT_NEAR(flight.speed(), expected, 1e-3 * expected) << h;
  }
}

// Issue 62, point 5: 2 m above the ground, four seconds of W moved the
// pilot 1.6 m (0.2 m/s per metre of height alone).
TEST(FlightControllerTest, NearTheGroundWMovesAtWalkingPaceOrBetter) {
  Body earth = load_body(find_body_file("earth"));
  Geodesy geodesy(earth.shape);
  FreeFlight flight(earth, Geodetic{glm::radians(46.55), glm::radians(7.98), 2.0}, 0.0);
  glm::dvec3 start = flight.camera().pos_body;
  FlightInput forward;
  forward.move = {0, 0, 1};
  for (int i = 0; i < 480; ++i) flight.step(1.0 / 120.0, 0.0, forward);
  double moved = glm::length(flight.camera().pos_body - start);
  EXPECT_GE(moved, 4.0 * 1.4) << "four seconds of W moved " << moved << " m";
  EXPECT_GE(flight.speed(), 1.4);
}

// A small body's ground lies below its ellipsoid in places: a start there
// keeps its height above the ground, not the ellipsoid's clearance (the
// asteroid's start was held 307.7 m above the ground where 30 m was asked).
TEST(FlightControllerTest, AStartBelowTheEllipsoidKeepsItsHeightAboveTheGround) {
  Body earth = load_body(find_body_file("earth"));
  const double ground = -307.2;
  FreeFlight flight(earth, Geodetic{0.3, 0.2, ground + 30.0}, 0.0);
  flight.set_ground([&](const Geodetic&) { return ground; });
  EXPECT_NEAR(flight.height_above_ground(), 30.0, 1e-6);
  FlightInput down;
  down.move = {0, -1, 0};
  down.boost = 10.0;
  for (int i = 0; i < 600; ++i) flight.step(1.0 / 120.0, 0.0, down);
  EXPECT_NEAR(flight.height_above_ground(), FreeFlight::kClearance, 1e-6);
}

TEST(FlightControllerTest, DivingNeverEntersTheGround) {
  Body earth = load_body(find_body_file("earth"));
  FreeFlight flight(earth, Geodetic{glm::radians(46.5), glm::radians(8.0), 3000.0}, 0.0);
  FlightInput dive;
  dive.turn = {-1, 0, 0};  // pitch down for 1.3 s: past straight down
  for (int i = 0; i < 160; ++i) flight.step(1.0 / 120.0, 0.0, dive);
  FlightInput down;
  down.move = {0, 0, 1};
  down.boost = 10.0;
  for (int i = 0; i < 6000; ++i) {
    flight.step(1.0 / 120.0, 0.0, down);
    ASSERT_GE(flight.height_above_ground(), FreeFlight::kClearance - 1e-6) << i;
  }
  EXPECT_LT(flight.height_above_ground(), 1.0);
}

TEST(FlightControllerTest, OrbitKeepsItsRadiusWhileTheBodyTurnsUnder) {
  Body earth = load_body(find_body_file("earth"));
  UtcSeconds t0 = parse_utc("2026-01-01T00:00:00Z", "t");
  KeplerOrbit orbit =
      circular_orbit_over(earth, Geodetic{0.0, 0.0, 400.0e3}, glm::radians(51.6), true, t0);
  OrbitFlight flight(earth, orbit, t0);
  double r0 = glm::length(flight.camera().pos_body);
  glm::dvec3 start = flight.camera().pos_body;
  flight.step(orbit.period(), t0 + orbit.period(), FlightInput{});
  EXPECT_NEAR(glm::length(flight.camera().pos_body), r0, 1e-3);
  // One orbit later the ground has turned east by period / sidereal day.
  Geodesy geodesy(earth.shape);
  double lon = geodesy.geodetic_from_body(flight.camera().pos_body).lon;
  EXPECT_NEAR(glm::degrees(lon), -360.0 * orbit.period() / earth.rotation.sidereal_period, 1e-6);
  EXPECT_NEAR(glm::length(flight.camera().pos_body - start), 2 * r0 * std::sin(std::abs(lon) / 2),
              1.0);
  // Speed in the body frame: orbital speed less the ground's turning.
  EXPECT_GT(flight.speed(), 7000.0);
  EXPECT_LT(flight.speed(), 8000.0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
