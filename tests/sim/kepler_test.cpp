// Two-body propagation: conserved quantities and Kepler's third law.
#include "sim/kepler.h"
#include "core/error.h"
#include "sim/body.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kMuEarth = 3.986004418e14;

double relative_drift(double a, double b) { return std::abs(a - b) / std::abs(a); }

TEST(KeplerTest, EnergyAndAngularMomentumHoldOverTenOrbits) {
  for (double e : {0.0, 0.3, 0.9}) {
    OrbitalElements el;
    el.semi_major_axis = 7.0e6 / (1.0 - e);  // periapsis above the ground
    el.eccentricity = e;
    el.inclination = glm::radians(51.6);
    el.ascending_node = glm::radians(40.0);
    el.periapsis_arg = glm::radians(70.0);
    el.mean_anomaly = 0.3;
    KeplerOrbit orbit = KeplerOrbit::from_elements(el, kMuEarth, 0.0);
    StateVector s0 = orbit.state_at(0.0);
    double energy0 = orbital_energy(s0, kMuEarth);
    glm::dvec3 h0 = angular_momentum(s0);
    double period = orbit.period();
    // Sample ten orbits at a step that never lands on the same anomaly.
    for (int i = 1; i <= 997; ++i) {
      double t = 10.0 * period * i / 997.0;
      StateVector s = orbit.state_at(t);
      ASSERT_LT(relative_drift(energy0, orbital_energy(s, kMuEarth)), 1e-9)
          << "e=" << e << " t=" << t;
      ASSERT_LT(glm::length(angular_momentum(s) - h0) / glm::length(h0), 1e-9) << "e=" << e;
    }
    // After whole periods the body is back where it started.
    EXPECT_LT(glm::length(orbit.state_at(10.0 * period).pos - s0.pos) / glm::length(s0.pos), 1e-9);
  }
}

TEST(KeplerTest, PeriodFollowsKeplersThirdLaw) {
  // The ISS-like circle: a = 6778 km, T = 2 pi sqrt(a^3 / mu).
  double a = 6778.0e3;
  StateVector s{{a, 0, 0}, {0, std::sqrt(kMuEarth / a), 0}};
  KeplerOrbit orbit = KeplerOrbit::from_state(s, kMuEarth, 0.0);
  double expected = 2 * glm::pi<double>() * std::sqrt(a * a * a / kMuEarth);
  EXPECT_NEAR(orbit.period(), expected, 1e-9 * expected);
  // Half a period later the body is on the other side of the circle.
  EXPECT_NEAR(orbit.state_at(0.5 * expected).pos.x, -a, 1e-6 * a);
  // A quarter period of true motion measured by the propagator.
  glm::dvec3 quarter = orbit.state_at(0.25 * expected).pos;
  EXPECT_NEAR(quarter.y, a, 1e-6 * a);
}

TEST(KeplerTest, StateRoundTripsThroughTheOrbit) {
  StateVector s{{7.0e6, 1.0e6, -2.0e6}, {-1000.0, 7000.0, 2500.0}};
  KeplerOrbit orbit = KeplerOrbit::from_state(s, kMuEarth, 100.0);
  StateVector back = orbit.state_at(100.0);
  EXPECT_LT(glm::length(back.pos - s.pos), 1e-6);
  EXPECT_LT(glm::length(back.vel - s.vel), 1e-9);
}

TEST(KeplerTest, CircularOrbitHasRequestedHeightAndInclination) {
  Body earth = load_body(find_body_file("earth"));
  Geodetic start{glm::radians(30.0), glm::radians(10.0), 400.0e3};
  UtcSeconds utc = parse_utc("2026-03-20T12:00:00Z", "test");
  KeplerOrbit orbit = circular_orbit_over(earth, start, glm::radians(51.6), true, utc);
  StateVector s = orbit.state_at(utc);
  glm::dvec3 h = glm::normalize(angular_momentum(s));
  EXPECT_NEAR(glm::degrees(std::acos(h.z)), 51.6, 1e-9);
  EXPECT_NEAR(orbit.eccentricity(), 0.0, 1e-12);
  // The body turns under the orbit: where it starts, it is over the place.
  Geodesy geodesy(earth.shape);
  Geodetic g = geodesy.geodetic_from_body(body_state(earth, s, utc).pos);
  EXPECT_NEAR(glm::degrees(g.lat), 30.0, 1e-9);
  EXPECT_NEAR(glm::degrees(g.lon), 10.0, 1e-9);
  EXPECT_NEAR(g.height, 400.0e3, 1e-3);
  // An inclination below the latitude never gets there.
  EXPECT_THROW(circular_orbit_over(earth, start, glm::radians(20.0), true, utc), InputError);
}

TEST(KeplerTest, UnboundStateIsAnInputError) {
  StateVector s{{7.0e6, 0, 0}, {0, 20000.0, 0}};
  EXPECT_THROW(KeplerOrbit::from_state(s, kMuEarth, 0.0), InputError);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
