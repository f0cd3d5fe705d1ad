// Earth's ground materials by rule (terrain/shaders/ground_material.glsl,
// the shader's own source compiled in double): each material's albedo
// against its source's range, the snow line against latitude, known places
// against what they are, and the land's mean albedo seen from orbit
// against the satellites'. Prints the places and the mean.
#include "terrain/ground_material.h"
#include "terrain/surface_maps.h"
#include "terrain/terrain_config.h"

#include "sim/body.h"
#include "sim/geodesy.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

using materials::GroundMaterial;

double mean(const glm::dvec3& c) { return (c.r + c.g + c.b) / 3.0; }

// 1 - cos of a tilt in degrees.
double slope_of(double tilt_deg) { return 1.0 - std::cos(glm::radians(tilt_deg)); }

TEST(GroundMaterialTest, EachMaterialsAlbedoLiesInItsSourcesRange) {
  // Broadband albedos: Oke 1987, table 1.1; rock from the ASTER library.
  EXPECT_GE(mean(materials::kSnowAlbedo), 0.80);
  EXPECT_LE(mean(materials::kSnowAlbedo), 0.90);
  EXPECT_GE(mean(materials::kRockAlbedo), 0.20);
  EXPECT_LE(mean(materials::kRockAlbedo), 0.30);
  EXPECT_GE(mean(materials::kForestAlbedo), 0.08);
  EXPECT_LE(mean(materials::kForestAlbedo), 0.15);
  EXPECT_GE(mean(materials::kGrassAlbedo), 0.20);
  EXPECT_LE(mean(materials::kGrassAlbedo), 0.25);
  EXPECT_GE(mean(materials::kDesertAlbedo), 0.30);
  EXPECT_LE(mean(materials::kDesertAlbedo), 0.40);
}

TEST(GroundMaterialTest, SnowLineStandsWhereTheTablesPutIt) {
  auto line = [](double lat_deg) { return materials::earth_snow_line(glm::radians(lat_deg)); };
  // Climatic snow lines (Wikipedia's "Snow line" table): the equator about
  // 4500-5000 m, the Himalaya's subtropics up to 5700, the Alps 2500-3200,
  // the polar circle 1000-1500, Svalbard 300-600, the sea at the poles.
  EXPECT_NEAR(line(0.0), 4700.0, 300.0);
  EXPECT_NEAR(line(28.0), 5000.0, 700.0);
  EXPECT_NEAR(line(47.0), 2850.0, 350.0);
  EXPECT_NEAR(line(-47.0), line(47.0), 1e-9);
  EXPECT_NEAR(line(66.5), 1250.0, 250.0);
  EXPECT_NEAR(line(78.0), 450.0, 150.0);
  EXPECT_EQ(line(90.0), 0.0);
  for (double lat = 25.0; lat < 90.0; lat += 1.0) EXPECT_GT(line(lat), line(lat + 1.0)) << lat;
}

class EarthMaterialsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::filesystem::path day = "/usr/share/xplanet/images/earth.jpg";
    if (!std::filesystem::exists(day)) {
      GTEST_SKIP() << day << " is not installed (Debian's xplanet-images)";
    }
    earth_ = load_body(find_body_file("earth"));
    config_ = parse_terrain(earth_);
    ASSERT_NE(config_.maps, nullptr);
    ASSERT_TRUE(config_.palette.materials) << "earth.json's albedo.materials is off";
  }
  glm::dvec3 dir(double lat_deg, double lon_deg) const {
    Geodesy g(earth_.shape);
    return glm::normalize(g.body_from_geodetic({glm::radians(lat_deg), glm::radians(lon_deg), 0}));
  }
  GroundMaterial at(double lat_deg, double lon_deg, double height, double tilt_deg) const {
    return materials::ground_material(slope_of(tilt_deg), height, glm::radians(lat_deg),
                                      config_.maps->day_color(dir(lat_deg, lon_deg)), true);
  }
  Body earth_;
  TerrainConfig config_;
};

TEST_F(EarthMaterialsTest, KnownPlacesHaveTheirMaterials) {
  struct Probe {
    const char* name;
    double lat, lon, height, tilt;
  };
  // Heights are the places' own (the grid's 9 km nodes blunt the summits);
  // tilts are the ground's.
  const Probe eiger{"Eiger north face", 46.577, 8.005, 3000.0, 60.0};
  const Probe mont_blanc{"Mont Blanc summit", 45.833, 6.865, 4806.0, 15.0};
  const Probe sahara{"Sahara, Great Sand Sea", 25.0, 25.0, 300.0, 2.0};
  const Probe amazon{"Amazon forest", -5.0, -62.0, 50.0, 1.0};
  const Probe beauce{"Beauce plain (France)", 47.0, 2.0, 120.0, 1.0};
  std::printf("%-24s %6s %6s %6s %6s %6s  %s\n", "place", "snow", "rock", "forest", "grass",
              "desert", "albedo (mean)");
  auto show = [&](const Probe& p) {
    GroundMaterial m = at(p.lat, p.lon, p.height, p.tilt);
    std::printf("%-24s %6.2f %6.2f %6.2f %6.2f %6.2f  %.3f %.3f %.3f (%.3f)\n", p.name, m.snow,
                m.rock, m.forest, m.grass, m.desert, m.albedo.r, m.albedo.g, m.albedo.b,
                mean(m.albedo));
    EXPECT_NEAR(m.snow + m.rock + m.forest + m.grass + m.desert, 1.0, 1e-9) << p.name;
    return m;
  };
  GroundMaterial m = show(eiger);
  EXPECT_GT(m.rock, 0.95);
  EXPECT_NEAR(mean(m.albedo), 0.25, 0.05);
  m = show(mont_blanc);
  EXPECT_GT(m.snow, 0.95);
  EXPECT_NEAR(mean(m.albedo), 0.85, 0.05);
  m = show(sahara);
  EXPECT_GT(m.desert, 0.9);
  EXPECT_NEAR(mean(m.albedo), 0.35, 0.05);
  m = show(amazon);
  EXPECT_GT(m.forest, 0.9);
  EXPECT_NEAR(mean(m.albedo), 0.115, 0.035);
  m = show(beauce);
  EXPECT_GT(m.grass, 0.8);
  EXPECT_NEAR(mean(m.albedo), 0.20, 0.05);
  // The same lowland with the slope of a cliff is rock; a gentle slope in
  // the Alps under the snow line is not snow.
  EXPECT_GT(at(beauce.lat, beauce.lon, 120.0, 50.0).rock, 0.95);
  EXPECT_EQ(at(46.6, 7.9, 1500.0, 10.0).snow, 0.0);
}

TEST_F(EarthMaterialsTest, LandSeenFromOrbitHasTheSatellitesMeanAlbedo) {
  // MODIS's white-sky broadband albedo of snow-free land lies within about
  // 0.1-0.35 (Schaaf et al. 2002, Remote Sens. Environ. 83, 135): the
  // rule's albedo, its RGB's mean, over land points 1 deg apart from 60 S
  // to 70 N weighted by their area, at the grid's heights, level (a
  // 100 km view averages slopes out), the ice sheets and snow left out.
  const double deg = glm::pi<double>() / 180.0;
  double sum = 0.0, weight = 0.0, image_sum = 0.0;
  int points = 0;
  for (double lat = -59.5; lat < 70.0; lat += 1.0) {
    for (double lon = -179.5; lon < 180.0; lon += 1.0) {
      glm::dvec3 d = dir(lat, lon);
      if (config_.maps->land(d) < 0.5) continue;
      double height = std::max(config_.heights->height(d), 0.0);
      glm::dvec3 c = config_.maps->day_color(d);
      GroundMaterial m = materials::ground_material(0.0, height, lat * deg, c, true);
      if (m.snow > 0.5) continue;
      double w = std::cos(lat * deg);
      sum += w * mean(m.albedo);
      // What the shader made of the image before: 0.42 c^1.2.
      image_sum += w * mean(0.42 * glm::pow(c, glm::dvec3(1.2)));
      weight += w;
      ++points;
    }
  }
  std::printf("land points %d: mean albedo %.3f (the image as 0.42 c^1.2: %.3f)\n", points,
              sum / weight, image_sum / weight);
  EXPECT_GT(points, 10000);
  EXPECT_GE(sum / weight, 0.10);
  EXPECT_LE(sum / weight, 0.35);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
