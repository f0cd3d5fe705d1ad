// The screen bound of a sphere holds every ray that meets it, and no more
// than the ellipse's own bounding rectangle.
#include "atmosphere/screen_bound.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// A camera turned by yaw and pitch, with a vertical field of view and an
// aspect, squeezed along one axis as atmosphere space squeezes an
// ellipsoid: (ndc.x, ndc.y, 1) to the ray's direction.
glm::dmat3 ray_from_ndc(double yaw, double pitch, double fov, double aspect, double squeeze) {
  glm::dmat3 turn = glm::dmat3(glm::rotate(glm::dmat4(1.0), yaw, glm::dvec3(0, 1, 0)) *
                               glm::rotate(glm::dmat4(1.0), pitch, glm::dvec3(1, 0, 0)));
  double t = std::tan(0.5 * fov);
  glm::dmat3 lens(glm::dvec3(t * aspect, 0, 0), glm::dvec3(0, t, 0), glm::dvec3(0, 0, -1));
  glm::dmat3 scale(1.0);
  scale[2][2] = squeeze;
  return scale * turn * lens;
}

TEST(ScreenBoundTest, HoldsEveryRayThatMeetsTheSphereAndTouchesItsEdges) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int bounded = 0;
  for (int trial = 0; trial < 400; ++trial) {
    glm::dmat3 m = ray_from_ndc(u(rng) * 6.28, (u(rng) - 0.5) * 3.0, 0.3 + u(rng) * 1.5,
                                1.0 + u(rng), 1.0 - 0.01 * u(rng));
    double radius = 6.46e6;
    double distance = radius * (1.0 + std::pow(10.0, -3.0 + 5.0 * u(rng)));
    glm::dvec3 dir = glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    glm::dvec3 center = distance * dir;
    auto rect = sphere_ndc_bound(center, radius, m);
    if (!rect) continue;
    ++bounded;
    glm::dmat3 to_q = glm::inverse(m);
    glm::dvec2 lo(1e30), hi(-1e30);
    // Rays toward points of the sphere, and toward its silhouette: the
    // circle where the rays from the camera graze it.
    glm::dvec3 c = center / distance;
    glm::dvec3 e1 = glm::normalize(glm::cross(c, std::abs(c.x) < 0.9 ? glm::dvec3(1, 0, 0)
                                                                       : glm::dvec3(0, 1, 0)));
    glm::dvec3 e2 = glm::cross(c, e1);
    double cos_a = std::sqrt(1.0 - (radius / distance) * (radius / distance));
    for (int i = 0; i < 4000; ++i) {
      glm::dvec3 on;
      if (i % 2) {
        double z = 2.0 * u(rng) - 1.0, phi = 6.28318 * u(rng);
        on = center + radius * glm::dvec3(std::sqrt(1 - z * z) * std::cos(phi),
                                          std::sqrt(1 - z * z) * std::sin(phi), z);
      } else {
        double theta = 6.283185307 * i / 4000.0;
        on = c * (distance * cos_a * cos_a) +
             radius * cos_a * (std::cos(theta) * e1 + std::sin(theta) * e2);
      }
      glm::dvec3 q = to_q * on;
      ASSERT_GT(q.z, 0.0) << "a bounded sphere lies in front of the camera";
      glm::dvec2 ndc(q.x / q.z, q.y / q.z);
      lo = glm::min(lo, ndc);
      hi = glm::max(hi, ndc);
      for (int a = 0; a < 2; ++a) {
        double slack = 1e-9 * (1.0 + std::abs(ndc[a]));
        EXPECT_GE(ndc[a], rect->min[a] - slack) << "trial " << trial;
        EXPECT_LE(ndc[a], rect->max[a] + slack) << "trial " << trial;
      }
    }
    // Tight: the silhouette reaches within a percent of each edge.
    for (int a = 0; a < 2; ++a) {
      double size = rect->max[a] - rect->min[a];
      EXPECT_LT(lo[a] - rect->min[a], 0.01 * size) << "trial " << trial;
      EXPECT_LT(rect->max[a] - hi[a], 0.01 * size) << "trial " << trial;
    }
  }
  EXPECT_GT(bounded, 50) << "of 400";
}

TEST(ScreenBoundTest, NoBoundFromInsideOrWithTheSphereBehind) {
  glm::dmat3 m = ray_from_ndc(0, 0, 1.0, 1.5, 1.0);
  EXPECT_FALSE(sphere_ndc_bound({0, 0, -10}, 20, m)) << "inside";
  EXPECT_FALSE(sphere_ndc_bound({0, 0, 30}, 20, m)) << "behind";
  EXPECT_FALSE(sphere_ndc_bound({30, 0, -5}, 20, m)) << "across the camera's plane";
  auto ahead = sphere_ndc_bound({0, 0, -1e3}, 1.0, m);
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(ahead->min.x, -ahead->max.x, 1e-12);
  EXPECT_LT(ahead->max.x, 0.01);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
