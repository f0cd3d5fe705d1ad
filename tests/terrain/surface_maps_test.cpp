// A body's day and night imagery: the land mask read from the day image's
// colours, the coastlines it gives the procedural heights, the bounds the
// level of detail relies on near those coasts, and the errors of a bad
// image or a missing one.
#include "terrain/surface_maps.h"
#include "terrain/procedural_height.h"
#include "terrain/terrain_config.h"

#include "core/data_paths.h"
#include "core/error.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

const std::filesystem::path kEarthDay = "/usr/share/xplanet/images/earth.jpg";

std::filesystem::path temp_file(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "planet_surface_maps_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

glm::dvec3 dir_at(double lat_deg, double lon_deg) {
  double lat = glm::radians(lat_deg), lon = glm::radians(lon_deg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// A direction `distance` metres (on a sphere of `radius`) from `d` toward
// a random bearing.
glm::dvec3 nearby(const glm::dvec3& d, double distance, double radius, std::mt19937& rng) {
  glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), d));
  glm::dvec3 north = glm::cross(d, east);
  double bearing = std::uniform_real_distribution<double>(0.0, 2.0 * glm::pi<double>())(rng);
  double angle = distance / radius;
  glm::dvec3 t = std::cos(bearing) * east + std::sin(bearing) * north;
  return glm::normalize(std::cos(angle) * d + std::sin(angle) * t);
}

// A 64 x 32 day image: open water (deep blue) west of longitude 0, green
// land east of it.
std::filesystem::path write_half_land(const std::string& name) {
  constexpr int w = 64, h = 32;
  std::vector<uint8_t> rgb(size_t(w * h * 3));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &rgb[size_t((y * w + x) * 3)];
      bool land = x >= w / 2;
      p[0] = land ? 60 : 2;
      p[1] = land ? 110 : 10;
      p[2] = land ? 30 : 60;
    }
  }
  auto file = temp_file(name);
  auto out = OIIO::ImageOutput::create(file.string());
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  out->open(file.string(), spec);
  out->write_image(OIIO::TypeDesc::UINT8, rgb.data());
  out->close();
  return file;
}

TEST(SurfaceMapsTest, TheLandMaskIsTheImagesWaterAndLandWithABlurredCoast) {
  SurfaceMaps maps({write_half_land("half.png"), {}}, 0.0);
  // A pixel is 5.625 deg; the blur reaches two pixels from the coasts at
  // longitudes 0 and 180.
  EXPECT_EQ(maps.land(dir_at(10.0, -90.0)), 0.0);
  EXPECT_EQ(maps.land(dir_at(-40.0, 90.0)), 1.0);
  double at_coast = maps.land(dir_at(0.0, 0.0));
  EXPECT_GT(at_coast, 0.3);
  EXPECT_LT(at_coast, 0.7);
  // The mask rises monotonically across the coast, west to east.
  double last = -1.0;
  for (double lon = -20.0; lon <= 20.0; lon += 0.5) {
    double v = maps.land(dir_at(5.0, lon));
    EXPECT_GE(v, last) << "at longitude " << lon;
    last = v;
  }
  // Wherever distance_to_coast says the coast is farther than r, the mask
  // holds one value within r.
  std::mt19937 rng(7);
  int checked = 0;
  for (double lon = -180.0; lon < 180.0; lon += 3.7) {
    for (double lat = -70.0; lat <= 70.0; lat += 7.3) {
      glm::dvec3 d = dir_at(lat, lon);
      double reach = maps.distance_to_coast(d);
      if (reach < 1e4) continue;
      double here = maps.land(d);
      for (int k = 0; k < 20; ++k) {
        glm::dvec3 e = nearby(d, reach * double(k + 1) / 20.0, 6371e3, rng);
        ASSERT_EQ(maps.land(e), here) << "lat " << lat << " lon " << lon << " reach " << reach;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(SurfaceMapsTest, BadImagesAreRefusedNamingTheFile) {
  auto expect_refused = [](const std::filesystem::path& file, const std::string& what) {
    try {
      SurfaceMaps maps({file, {}}, 0.0);
      FAIL() << "no error for " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
  };
  // Not twice as wide as high.
  {
    auto file = temp_file("square.png");
    auto out = OIIO::ImageOutput::create(file.string());
    std::vector<uint8_t> rgb(16 * 16 * 3, 100);
    OIIO::ImageSpec spec(16, 16, 3, OIIO::TypeDesc::UINT8);
    out->open(file.string(), spec);
    out->write_image(OIIO::TypeDesc::UINT8, rgb.data());
    out->close();
    expect_refused(file, "a square image");
  }
  // A JPEG's first bytes and then garbage.
  {
    auto file = temp_file("garbage.jpg");
    std::ofstream(file, std::ios::binary) << "\xFF\xD8\xFF\xE0 not a JPEG at all";
    expect_refused(file, "a broken JPEG");
  }
  // A real JPEG cut in half: libjpeg would fill the rest with grey.
  {
    std::filesystem::path seeds = project_root() / "tests" / "fuzz" / "corpus" / "surface_maps";
    std::ifstream in(seeds / "ed53e050c1dd26d5", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 100u);
    ASSERT_EQ(bytes[0], '\0');  // the fuzz target's choice of extension, then the file
    auto file = temp_file("truncated.jpg");
    std::ofstream(file, std::ios::binary) << bytes.substr(1, bytes.size() / 2);
    expect_refused(file, "a truncated JPEG");
  }
  // A text file, a directory, a file that is not there.
  {
    auto file = temp_file("text.png");
    std::ofstream(file) << "hello";
    expect_refused(file, "a text file");
  }
  expect_refused(std::filesystem::temp_directory_path(), "a directory");
  expect_refused(temp_file("absent.png"), "a missing file");
}

TEST(SurfaceMapsTest, ABodyWhoseImageryIsNotInstalledKeepsItsPalette) {
  Body earth = load_body(data_dir() / "planets" / "earth.json");
  earth.terrain["maps"]["day"] = temp_file("not_installed.jpg").string();
  TerrainConfig config = parse_terrain(earth);
  EXPECT_EQ(config.maps, nullptr);
  // The procedural continents then: some sea and some land.
  int sea = 0, land = 0;
  for (double lon = -180.0; lon < 180.0; lon += 10.0) {
    for (double lat = -60.0; lat <= 60.0; lat += 10.0) {
      (config.heights->height(dir_at(lat, lon)) <= 0.0 ? sea : land) += 1;
    }
  }
  EXPECT_GT(sea, 20);
  EXPECT_GT(land, 20);
}

class EarthImageryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kEarthDay)) {
      GTEST_SKIP() << kEarthDay << " is not installed (Debian's xplanet-images; "
                   << "scripts/install-deps.sh installs it)";
    }
    // The procedural Earth, whose noise the imagery's land mask shapes.
    earth_ = load_body(project_root() / "tests/data/planets/earth_procedural.json");
    config_ = parse_terrain(earth_);
    ASSERT_NE(config_.maps, nullptr);
  }
  Body earth_;
  TerrainConfig config_;
};

TEST_F(EarthImageryTest, EarthsSeasAndLandsAreWhereTheBlueMarbleHasThem) {
  const SurfaceMaps& maps = *config_.maps;
  const HeightSource& h = *config_.heights;
  // Places everyone knows.
  EXPECT_EQ(h.height(dir_at(0.0, -150.0)), 0.0) << "mid-Pacific";
  EXPECT_EQ(h.height(dir_at(30.0, -40.0)), 0.0) << "mid-Atlantic";
  EXPECT_EQ(h.height(dir_at(-30.0, 80.0)), 0.0) << "Indian Ocean";
  EXPECT_EQ(h.height(dir_at(35.0, 18.0)), 0.0) << "Ionian Sea";
  for (auto [lat, lon, name] : {std::tuple{23.0, 10.0, "Sahara"},
                                {45.0, 90.0, "Mongolia"},
                                {-5.0, -60.0, "Amazon"},
                                {-25.0, 135.0, "Australia"},
                                {40.0, -100.0, "Kansas"},
                                {46.55, 7.98, "the Alps"}}) {
    EXPECT_GE(h.height(dir_at(lat, lon)), ProceduralHeight::kLandAbove - 1e-9) << name;
  }
  // Every point of a 1-degree grid where the image's mask is settled (no
  // coast within two pixels): water is sea, land stands over it.
  int water = 0, land = 0;
  for (double lat = -80.0; lat <= 80.0; lat += 1.0) {
    for (double lon = -180.0; lon < 180.0; lon += 1.0) {
      glm::dvec3 d = dir_at(lat, lon);
      double m = maps.land(d);
      if (m == 0.0) {
        ++water;
        ASSERT_EQ(h.height(d), 0.0) << "lat " << lat << " lon " << lon;
      } else if (m == 1.0) {
        ++land;
        ASSERT_GE(h.height(d), ProceduralHeight::kLandAbove - 1e-9)
            << "lat " << lat << " lon " << lon;
      }
    }
  }
  std::printf("settled water %d, land %d of %d grid points\n", water, land, 161 * 360);
  EXPECT_GT(water, 161 * 360 / 2);
  EXPECT_GT(land, 161 * 360 / 5);
}

TEST_F(EarthImageryTest, FarInlandTheHeightsAreTheNoisesOwn) {
  // The Alps' flights keep their ground: a ProceduralHeight without the
  // mask gives the same heights where the noise stands well over the sea.
  const auto& shaped = dynamic_cast<const ProceduralHeight&>(*config_.heights);
  Body plain_body = earth_;
  plain_body.terrain.erase("maps");
  TerrainConfig plain = parse_terrain(plain_body);
  int same = 0;
  for (double lat = 46.0; lat <= 47.0; lat += 0.05) {
    for (double lon = 7.0; lon <= 9.0; lon += 0.05) {
      glm::dvec3 d = dir_at(lat, lon);
      double h0 = plain.heights->height(d);
      if (h0 < ProceduralHeight::kLandAbove + ProceduralHeight::kSoftening) continue;
      ASSERT_EQ(shaped.height(d), h0) << "lat " << lat << " lon " << lon;
      ++same;
    }
  }
  EXPECT_GT(same, 500);
}

TEST_F(EarthImageryTest, RangesAndInterpolationErrorsHoldAcrossCoasts) {
  const HeightSource& h = *config_.heights;
  std::mt19937 rng(11);
  // Around coasts: the Strait of Gibraltar, Italy's heel, the Norwegian
  // fjords, the Bahamas, the Bosporus.
  for (auto [lat, lon] :
       {std::pair{36.0, -5.6}, {40.3, 18.3}, {61.0, 5.5}, {24.5, -77.5}, {41.1, 29.0}}) {
    glm::dvec3 d = dir_at(lat, lon);
    for (double radius : {2e3, 2e4, 1e5}) {
      HeightRange r = h.range_near(d, radius);
      for (int k = 0; k < 300; ++k) {
        double dist = radius * std::sqrt(std::uniform_real_distribution<double>(0, 1)(rng));
        double v = h.height(nearby(d, dist, 6371e3, rng));
        ASSERT_GE(v, r.min - 1e-6) << "lat " << lat << " lon " << lon << " radius " << radius;
        ASSERT_LE(v, r.max + 1e-6) << "lat " << lat << " lon " << lon << " radius " << radius;
      }
    }
    for (double spacing : {30.0, 300.0, 3000.0, 30000.0}) {
      double bound = h.interpolation_error(spacing);
      for (int k = 0; k < 200; ++k) {
        glm::dvec3 a =
            nearby(d, 3e4 * std::uniform_real_distribution<double>(0, 1)(rng), 6371e3, rng);
        glm::dvec3 b = nearby(a, spacing, 6371e3, rng);
        glm::dvec3 mid = glm::normalize(a + b);
        ASSERT_NEAR(h.height(mid), 0.5 * (h.height(a) + h.height(b)), bound)
            << "lat " << lat << " lon " << lon << " spacing " << spacing;
      }
    }
  }
  HeightRange all = h.range();
  EXPECT_LE(all.min, 0.0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
