// The albedo's variation over the ground: Mars's bright and dark provinces
// seen from orbit, detail down to the metre near the ground, and no octave
// finer than the samples that carry it.
#include "terrain/surface_color.h"

#include "core/data_paths.h"
#include "sim/body.h"
#include "terrain/terrain_config.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// Points over a sphere of `radius`, or within `extent` metres of one point.
std::vector<glm::dvec3> points(double radius, double extent, int count) {
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  std::vector<glm::dvec3> out;
  const glm::dvec3 centre = radius * glm::normalize(glm::dvec3(0.3, 0.4, 0.5));
  for (int i = 0; i < count; ++i) {
    if (extent <= 0) {
      out.push_back(radius * glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng))));
    } else {
      out.push_back(centre + extent * glm::dvec3(uniform(rng), uniform(rng), uniform(rng)));
    }
  }
  return out;
}

// The ratio of the 90th to the 10th percentile of the factor.
double spread(const std::vector<AlbedoVariation>& variation, const std::vector<glm::dvec3>& at,
              double spacing) {
  std::vector<double> f;
  for (const glm::dvec3& p : at) f.push_back(albedo_variation(variation, p, spacing));
  std::sort(f.begin(), f.end());
  return f[f.size() * 9 / 10] / f[f.size() / 10];
}

TEST(SurfaceColorTest, MarsHasBrightAndDarkProvincesAndDetailNearTheGround) {
  Body mars = load_body(data_dir() / "planets" / "mars.json");
  const SurfacePalette& palette = parse_terrain(mars).palette;
  ASSERT_FALSE(palette.variation.empty());
  const double radius = mars.shape.equatorial_radius;
  // Over the globe, sampled every 10 km as a tile seen from orbit carries
  // it: the brighter tenth at least 1.5 times the darker.
  double globe = spread(palette.variation, points(radius, 0.0, 2000), 10e3);
  // Within 50 m of one place, every 0.5 m as the ground under a lander.
  double ground = spread(palette.variation, points(radius, 50.0, 2000), 0.5);
  std::printf("Mars's albedo: 90th / 10th percentile %.2f over the globe, %.2f within 50 m\n",
              globe, ground);
  EXPECT_GT(globe, 1.5);
  EXPECT_GT(ground, 1.15);
}

TEST(SurfaceColorTest, NoOctaveFinerThanTwiceTheSpacing) {
  std::vector<AlbedoVariation> fine = {{30.0, 4, 0.5, 0.3, 9}};
  // The coarsest octave (30 m) is below twice a 20 m spacing: nothing left.
  for (const glm::dvec3& p : points(3e6, 1e4, 200)) {
    EXPECT_EQ(albedo_variation(fine, p, 20.0), 1.0);
  }
  EXPECT_GT(spread(fine, points(3e6, 1e4, 2000), 1.0), 1.2);
}

TEST(SurfaceColorTest, FactorStaysWithinItsBounds) {
  std::vector<AlbedoVariation> loud = {{1e3, 6, 0.5, 0.95, 1}, {50.0, 6, 0.5, 0.95, 2}};
  for (const glm::dvec3& p : points(1e6, 1e5, 2000)) {
    double f = albedo_variation(loud, p, 0.1);
    EXPECT_GE(f, 0.05);
    EXPECT_LE(f, 2.0);
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
