// The occluded sun (atmosphere/shaders/occluded_sun.glsl, compiled as C++
// double) against a brute-force integral of sun.glsl's limb-darkened disk
// over a fine grid of directions, each tested against the Moon's sphere.
#include "atmosphere/math/shared_math.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kSunRadius = 4.65e-3;   // rad, the sun's angular radius from the Earth
constexpr double kMoonDistance = 3.8e8;  // m

// The Moon whose disk has radius rho and centre d from the sun's, both in
// sun radii, the sun toward +z; its radius and centre relative to the point.
struct MoonPlace {
  glm::dvec3 centre;
  double radius;
};
MoonPlace moon_at(double d, double rho) {
  double separation = d * kSunRadius;
  glm::dvec3 dir(std::sin(separation), 0.0, std::cos(separation));
  return {kMoonDistance * dir, kMoonDistance * std::sin(rho * kSunRadius)};
}

// The visible share of sun_disk_radiance's flux: a square grid of
// directions on the plane tangent to the sky at the sun (1400 pixels
// across its disk), each weighted by the disk's radiance and its solid
// angle and tested against the Moon's sphere. Each pixel on the Moon's
// edge counts whole or not at all, at random over the edge: about 1e-5 of
// the disk's flux in all.
struct SunSample {
  glm::dvec3 dir;
  glm::dvec3 flux;
};
const std::vector<SunSample>& sun_grid() {
  static const std::vector<SunSample> grid = [] {
    constexpr int kAcross = 1400;
    shared::Atmosphere a{};
    a.solar_irradiance = glm::dvec3(1.0);
    a.sun_angular_radius = kSunRadius;
    double half = std::tan(kSunRadius), step = 2.0 * half / kAcross;
    std::vector<SunSample> samples;
    for (int i = 0; i < kAcross; ++i) {
      for (int j = 0; j < kAcross; ++j) {
        glm::dvec3 plane(-half + (i + 0.5) * step, -half + (j + 0.5) * step, 1.0);
        double length = glm::length(plane);
        glm::dvec3 radiance = shared::sun_disk_radiance(a, 1.0 / length);
        if (radiance.g <= 0.0) continue;
        // The solid angle of a pixel of the tangent plane: step^2 / |p|^3.
        samples.push_back({plane / length, radiance * step * step / (length * length * length)});
      }
    }
    return samples;
  }();
  return grid;
}

glm::dvec3 brute_force_fraction(const MoonPlace& moon) {
  glm::dvec3 moon_dir = glm::normalize(moon.centre);
  double cos_moon = std::cos(std::asin(moon.radius / glm::length(moon.centre)));
  glm::dvec3 visible(0.0), total(0.0);
  for (const SunSample& s : sun_grid()) {
    total += s.flux;
    if (glm::dot(s.dir, moon_dir) <= cos_moon) visible += s.flux;
  }
  return visible / total;
}

glm::dvec3 fraction(const MoonPlace& moon) {
  return shared::occluded_sun_fraction(glm::dvec3(0, 0, 1), kSunRadius, moon.centre, moon.radius);
}

TEST(OccludedSunTest, AgreesWithABruteForceIntegralInEveryPhase) {
  // Moons smaller than the sun (annular), about its size and larger (the
  // 2024 eclipse's was 1.054 sun radii); separations from centred through
  // the inner contacts to grazing.
  double worst_relative = 0, worst_absolute = 0;
  for (double rho : {0.5, 0.92, 0.99, 1.0, 1.03, 1.054, 1.5}) {
    std::vector<double> separations;
    for (int k = 0; k <= 12; ++k) separations.push_back((1.0 + rho) * k / 12.0);
    for (double offset : {-0.01, 0.01}) separations.push_back(std::abs(1.0 - rho) + offset);
    separations.push_back(1.0 + rho - 0.005);  // grazing
    for (double d : separations) {
      if (d < 0.0) continue;
      MoonPlace moon = moon_at(d, rho);
      glm::dvec3 expected = brute_force_fraction(moon), got = fraction(moon);
      for (int c = 0; c < 3; ++c) {
        double error = std::abs(got[c] - expected[c]);
        worst_absolute = std::max(worst_absolute, error);
        EXPECT_LE(error, 5e-4) << "rho " << rho << " d " << d << " channel " << c;
        if (expected[c] > 0.01) {
          worst_relative = std::max(worst_relative, error / expected[c]);
          EXPECT_LE(error / expected[c], 1e-3) << "rho " << rho << " d " << d << " channel " << c;
        }
      }
    }
  }
  std::printf("worst error: %.2e of the visible share (where over 1 %%), %.2e of the disk\n",
              worst_relative, worst_absolute);
}

TEST(OccludedSunTest, ExactWithNoOverlapFullCoverAndACentredMoon) {
  EXPECT_EQ(fraction(moon_at(2.06, 1.05)), glm::dvec3(1.0));
  EXPECT_EQ(fraction(moon_at(0.04, 1.05)), glm::dvec3(0.0));
  // Centred, a Moon of radius rho leaves the flux outside rho:
  // (1 - rho^2)^(alpha / 2 + 1).
  const double alpha[] = {0.397, 0.503, 0.652};  // sun.glsl's limb darkening
  for (double rho : {0.3, 0.95}) {
    glm::dvec3 got = fraction(moon_at(0.0, rho));
    for (int c = 0; c < 3; ++c) {
      double expected = std::pow(1.0 - rho * rho, alpha[c] / 2.0 + 1.0);
      EXPECT_NEAR(got[c], expected, 1e-6) << "rho " << rho;
    }
  }
  // Inside the Moon, no sun.
  EXPECT_EQ(shared::occluded_sun_fraction(glm::dvec3(0, 0, 1), kSunRadius, glm::dvec3(0, 0, 1e5),
                                          1.7374e6),
            glm::dvec3(0.0));
}

TEST(OccludedSunTest, FallsSmoothlyAndNeverRisesThroughTheContacts) {
  // The Moon crossing to the sun's centre: a total (rho 1.054) and an
  // annular (0.95) eclipse, through first and second contact. No step may
  // rise, and none may jump: the share changes by at most its slope's
  // bound (about 2 per sun radius, the disk's diameter) times the step.
  for (double rho : {1.054, 0.95}) {
    constexpr int kSteps = 4000;
    double d_max = 1.0 + rho + 0.01;
    glm::dvec3 last = fraction(moon_at(d_max, rho));
    for (int k = 1; k <= kSteps; ++k) {
      double d = d_max * (1.0 - double(k) / kSteps);
      glm::dvec3 now = fraction(moon_at(d, rho));
      for (int c = 0; c < 3; ++c) {
        ASSERT_LE(now[c], last[c] + 1e-12) << "rho " << rho << " d " << d << " channel " << c;
        ASSERT_LE(last[c] - now[c], 2.0 * d_max / kSteps) << "rho " << rho << " d " << d;
      }
      last = now;
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
