// The shared math (atmosphere/shaders/*.glsl, atmosphere/math/shared_math.h, compiled as
// C++ double) against closed forms.
#include "atmosphere/math/shared_math.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

using shared::Atmosphere;

// A shell with one component of the given density profile, coefficient 1/m.
Atmosphere one_layer_atmosphere(double bottom, double top, const shared::DensityLayer& layer) {
  Atmosphere a{};
  a.bottom_radius = bottom;
  a.top_radius = top;
  a.rayleigh_scattering = shared::Real3(1e-5, 2e-5, 3e-5);
  a.rayleigh_density.layers[1] = layer;
  return a;
}

const double kZenithAnglesDeg[] = {0.0, 30.0, 60.0, 80.0, 85.0, 89.0, 90.0, 95.0};

TEST(SharedMathTest, ConstantDensityOpticalDepthIsCoefficientTimesLength) {
  Atmosphere a = one_layer_atmosphere(6360e3, 6460e3, {0, 0, 0, 0, 1});
  for (double r : {6360e3 + 1.0, 6400e3, 6459e3}) {
    for (double zenith : kZenithAnglesDeg) {
      double mu = std::cos(glm::radians(zenith));
      if (shared::ray_intersects_ground(a, r, mu)) continue;
      double length = shared::distance_to_top_boundary(a, r, mu);
      glm::dvec3 tau = shared::optical_depth_to_top(a, r, mu, 64);
      glm::dvec3 expected = a.rayleigh_scattering * length;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(tau[c] / expected[c], 1.0, 1e-4) << "r " << r << " zenith " << zenith;
      }
      // Transmittance too, as a technique would use it.
      EXPECT_NEAR(std::exp(-tau.g) / std::exp(-expected.g), 1.0, 1e-4);
    }
  }
}

// The reference for an exponential layer: the numerical optical depth with
// enough steps that the trapezoid rule's error (O(h^2)) is below 1e-7.
TEST(SharedMathTest, ExponentialOpticalDepthAnalyticMatchesQuadrature) {
  for (double H : {8000.0, 1200.0}) {
    Atmosphere a = one_layer_atmosphere(6360e3, 6460e3, {0, 1, -1.0 / H, 0, 0});
    for (double r : {6360e3, 6361e3, 6380e3, 6420e3}) {
      for (double zenith : kZenithAnglesDeg) {
        double mu = std::cos(glm::radians(zenith));
        if (shared::ray_intersects_ground(a, r, mu)) continue;
        double numeric = shared::optical_depth_to_top(a, r, mu, 200000).r / a.rayleigh_scattering.r;
        double analytic = shared::exponential_optical_depth_to_top(a, H, r, mu);
        EXPECT_NEAR(analytic / numeric, 1.0, 1e-4)
            << "H " << H << " r " << r << " zenith " << zenith;
        double t_numeric = std::exp(-a.rayleigh_scattering.b * numeric);
        double t_analytic = std::exp(-a.rayleigh_scattering.b * analytic);
        EXPECT_NEAR(t_analytic / t_numeric, 1.0, 1e-4);
      }
    }
  }
}

TEST(SharedMathTest, ChapmanVerticalIsTheScaleHeight) {
  // Straight up to infinity: the integral of exp(-z / H) is exactly H; the
  // expansion's neglected terms are O((H / r)^2 / mu^4), 1.6e-6 * 4 here.
  EXPECT_NEAR(shared::chapman_optical_depth_to_infinity(6360e3, 8000.0, 6360e3, 1.0) / 8000.0, 1.0,
              2e-5);
  // Horizontal: sqrt(pi r H / 2) to leading order (Chapman 1931).
  double horizontal = shared::chapman_optical_depth_to_infinity(6360e3, 8000.0, 6360e3, 0.0);
  EXPECT_NEAR(horizontal / std::sqrt(shared::kPi * 6360e3 * 8000.0 / 2.0), 1.0, 2e-3);
}

TEST(SharedMathTest, TransmittanceLutMappingRoundTrips) {
  Atmosphere a = one_layer_atmosphere(6360e3, 6460e3, {0, 0, 0, 0, 1});
  shared::Real2 size(256.0, 64.0);
  // Not at the top itself: there every upward ray has length 0, and the
  // mapping sends them all to u = 0.5 / width.
  for (double r : {6360e3, 6360e3 + 10.0, 6400e3, 6459e3}) {
    for (double mu : {-0.2, -0.05, 0.0, 0.1, 0.5, 0.99, 1.0}) {
      if (shared::ray_intersects_ground(a, r, mu)) continue;
      shared::Real2 uv = shared::transmittance_uv_from_r_mu(a, r, mu, size);
      EXPECT_GE(uv.x, 0.5 / size.x - 1e-12);
      EXPECT_LE(uv.x, 1.0 - 0.5 / size.x + 1e-12);
      shared::Real2 back = shared::transmittance_r_mu_from_uv(a, uv, size);
      EXPECT_NEAR(back.x, r, 1e-6 * r) << r << " " << mu;
      EXPECT_NEAR(back.y, mu, 1e-6) << r << " " << mu;
    }
  }
  // The corners: the ground's horizon and the zenith at the top.
  shared::Real2 horizon = shared::transmittance_uv_from_r_mu(a, 6360e3, 0.0, size);
  EXPECT_NEAR(horizon.x, 1.0 - 0.5 / size.x, 1e-9);
  EXPECT_NEAR(horizon.y, 0.5 / size.y, 1e-9);
}

TEST(SharedMathTest, RayShellStopsAtTheGroundAndStartsAtTheTop) {
  shared::Real3 up(0, 0, 1);
  double t0, t1;
  // From the ground straight up: the whole shell.
  ASSERT_TRUE(shared::ray_shell(shared::Real3(0, 0, 6360e3), up, 6360e3, 6460e3, t0, t1));
  EXPECT_NEAR(t0, 0.0, 1e-9);
  EXPECT_NEAR(t1, 100e3, 1e-6);
  // From space straight down: from the top to the ground.
  ASSERT_TRUE(shared::ray_shell(shared::Real3(0, 0, 1e9), -up, 6360e3, 6460e3, t0, t1));
  EXPECT_NEAR(t0, 1e9 - 6460e3, 1e-3);
  EXPECT_NEAR(t1, 1e9 - 6360e3, 1e-3);
  // From 1e9 m, a grazing ray 1 m above the top misses; 1 m below it hits
  // the shell in a chord of 2 sqrt(2 R 1 m) = 7.19 km.
  shared::Real3 far(-1e9, 0, 6460e3 + 1.0);
  EXPECT_FALSE(shared::ray_shell(far, shared::Real3(1, 0, 0), 6360e3, 6460e3, t0, t1));
  far.z = 6460e3 - 1.0;
  ASSERT_TRUE(shared::ray_shell(far, shared::Real3(1, 0, 0), 6360e3, 6460e3, t0, t1));
  EXPECT_NEAR(t1 - t0, 2.0 * std::sqrt(2.0 * 6460e3 - 1.0), 1e-3);
  // Pointing away from the shell from outside: nothing.
  EXPECT_FALSE(shared::ray_shell(shared::Real3(0, 0, 1e9), up, 6360e3, 6460e3, t0, t1));
}

TEST(SharedMathTest, PhaseFunctionsIntegrateToOne) {
  for (double g : {0.0, 0.5, 0.8, 0.95}) {
    double hg = 0, cs = 0, rayleigh = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      double nu = -1.0 + 2.0 * (i + 0.5) / n;
      double w = 2.0 * shared::kPi * 2.0 / n;
      hg += w * shared::henyey_greenstein_phase(g, nu);
      cs += w * shared::cornette_shanks_phase(g, nu);
      rayleigh += w * shared::rayleigh_phase(nu);
    }
    EXPECT_NEAR(hg, 1.0, 1e-3) << g;
    EXPECT_NEAR(cs, 1.0, 1e-3) << g;
    EXPECT_NEAR(rayleigh, 1.0, 1e-6);
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
