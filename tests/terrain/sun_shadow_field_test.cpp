// The terrain's shadow in the air: the shadow-height field against a fine
// march of the sun's ray over the height source itself, and its purity (the
// same frame gives the same bytes whatever came before).
#include "terrain/sun_shadow_field.h"

#include "core/data_paths.h"
#include "terrain/terrain_config.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kRadius = 6.36e6;

// A round hill of `peak` metres with a Gaussian profile of width `sigma`
// metres about a direction, on a smooth sphere.
class Hill final : public HeightSource {
 public:
  Hill(glm::dvec3 top, double peak, double sigma) : top_(top), peak_(peak), sigma_(sigma) {}
  double height(const glm::dvec3& dir) const override {
    double d = kRadius * std::acos(std::clamp(glm::dot(dir, top_), -1.0, 1.0));
    return peak_ * std::exp(-(d * d) / (sigma_ * sigma_));
  }
  HeightRange range_near(const glm::dvec3&, double) const override { return {0, peak_}; }
  HeightRange range() const override { return {0, peak_}; }
  double interpolation_error(double) const override { return peak_; }

 private:
  glm::dvec3 top_;
  double peak_, sigma_;
};

TerrainSurface hill_surface(const glm::dvec3& top, double peak, double sigma) {
  Body body = load_body(data_dir() / "planets" / "earth.json");
  body.terrain = nullptr;
  body.shape.equatorial_radius = kRadius;
  body.shape.flattening = 0;
  TerrainConfig config = parse_terrain(body);
  config.heights = std::make_shared<Hill>(top, peak, sigma);
  return TerrainSurface(body.shape, config);
}

glm::dvec3 from_lat_lon(double lat_deg, double lon_deg) {
  double lat = glm::radians(lat_deg), lon = glm::radians(lon_deg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// The lowest altitude above `dir` from which the sun's ray clears the
// ground, marched over the height source in 20 m steps and bisected to a
// metre.
double marched_shadow_height(const TerrainSurface& surface, const glm::dvec3& dir,
                             const glm::dvec3& sun) {
  double ground = 0;
  surface.point(dir, &ground);
  auto lit = [&](double z) {
    glm::dvec3 p0 = (kRadius + z) * dir;
    for (double d = 20.0; d < 60e3; d += 20.0) {
      glm::dvec3 p = p0 + d * sun;
      double r = glm::length(p);
      if (r - kRadius > 3000.0) return true;
      if (r - kRadius < surface.heights().height(p / r)) return false;
    }
    return true;
  };
  if (lit(ground)) return ground;
  double lo = ground, hi = ground + 3000.0;
  while (hi - lo > 1.0) {
    double mid = 0.5 * (lo + hi);
    (lit(mid) ? hi : lo) = mid;
  }
  return hi;
}

TEST(SunShadowFieldTest, ShadowHeightsMatchAMarchOverTheGround) {
  // A 1500 m hill 10 km east of the camera; the sun 3 degrees up in the
  // east, so the hill's shadow runs west over the camera's patch.
  const glm::dvec3 camera_dir = from_lat_lon(45.0, 7.0);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), camera_dir));
  const glm::dvec3 top = glm::normalize(camera_dir + (10e3 / kRadius) * east);
  TerrainSurface surface = hill_surface(top, 1500.0, 3000.0);
  const double e = glm::radians(3.0);
  const glm::dvec3 sun = glm::normalize(std::cos(e) * east + std::sin(e) * camera_dir);

  SunShadowField field;
  ASSERT_TRUE(
      field.update(surface, glm::dvec3(1.0), kRadius, (kRadius + 3000.0) * camera_dir, sun));
  const ShadowPatch& patch = field.patch();
  // Across the shadow, from the hill westward 25 km, and across it north
  // and south.
  int shadowed = 0;
  double worst = 0;
  for (double along = -25e3; along <= 10e3; along += 2.5e3) {
    for (double across = -6e3; across <= 6e3; across += 1.5e3) {
      double x = 0, y = 0;
      glm::dvec3 q = glm::normalize(top + (along / kRadius) * east +
                                    (across / kRadius) * glm::cross(top, east));
      ASSERT_TRUE(patch.plane(q, x, y));
      double marched = marched_shadow_height(surface, q, sun);
      double ground = 0;
      surface.point(q, &ground);
      shadowed += marched > ground + 50.0;
      worst = std::max(worst, std::abs(field.shadow_height(x, y) - marched));
    }
  }
  EXPECT_GT(shadowed, 25);
  // Half a cell's ground (500 m cells over a hill 3 km wide) and the
  // ray's rise over half a cell.
  EXPECT_LT(worst, 50.0);
}

TEST(SunShadowFieldTest, AHighSunOrAFlatGroundCastsNoShadow) {
  const glm::dvec3 camera_dir = from_lat_lon(-20.0, 100.0);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), camera_dir));
  {
    TerrainSurface flat = hill_surface(camera_dir, 0.0, 3000.0);
    SunShadowField field;
    field.update(flat, glm::dvec3(1.0), kRadius, kRadius * camera_dir,
                 glm::normalize(east + 0.02 * camera_dir));
    for (size_t n = 0; n < field.shadow().size(); ++n) {
      ASSERT_EQ(field.shadow()[n], field.ground()[n]) << n;
    }
  }
  TerrainSurface hill = hill_surface(camera_dir, 1500.0, 3000.0);
  SunShadowField field;
  field.update(hill, glm::dvec3(1.0), kRadius, kRadius * camera_dir,
               glm::normalize(east + 2.0 * camera_dir));  // 63 degrees up
  for (size_t n = 0; n < field.shadow().size(); ++n) {
    ASSERT_EQ(field.shadow()[n], field.ground()[n]) << n;
  }
}

TEST(SunShadowFieldTest, TheFieldIsAFunctionOfTheFrameAlone) {
  const glm::dvec3 camera_dir = from_lat_lon(45.0, 7.0);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), camera_dir));
  TerrainSurface surface = hill_surface(camera_dir, 1500.0, 3000.0);
  const glm::dvec3 camera = (kRadius + 2000.0) * camera_dir;
  const glm::dvec3 sun = glm::normalize(east + 0.05 * camera_dir);

  SunShadowField direct;
  direct.update(surface, glm::dvec3(1.0), kRadius, camera, sun);
  // Another field that came there from elsewhere, and through a camera
  // and a sun a hair away (within the lattice and the sun's step).
  SunShadowField travelled;
  travelled.update(surface, glm::dvec3(1.0), kRadius, (kRadius + 9000.0) * from_lat_lon(46.0, 8.0),
                   glm::normalize(east + 0.2 * camera_dir));
  travelled.update(surface, glm::dvec3(1.0), kRadius, camera + 200.0 * east,
                   glm::normalize(sun + glm::dvec3(1e-6)));
  const uint64_t version = travelled.version();
  EXPECT_FALSE(travelled.update(surface, glm::dvec3(1.0), kRadius, camera, sun));
  EXPECT_EQ(travelled.version(), version);
  ASSERT_EQ(direct.shadow().size(), travelled.shadow().size());
  EXPECT_EQ(0, std::memcmp(direct.shadow().data(), travelled.shadow().data(),
                           direct.shadow().size() * sizeof(float)));
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
