// Height sources: the height map reader and its bad inputs, and the body
// file's terrain block.
#include "terrain/height_map.h"
#include "terrain/terrain_config.h"

#include "core/error.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::filesystem::path temp_file(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "planet_height_source_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

void write_map(const std::filesystem::path& file, int w, int h, const std::vector<float>& v) {
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::FLOAT);
  ASSERT_TRUE(out->open(file.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, v.data()));
  out->close();
}

// The error message must name the file.
void expect_error_naming(const std::filesystem::path& file, const std::string& what) {
  try {
    HeightMap map(file, 1.0, 0.0);
    FAIL() << "no error for " << what;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST(HeightMapTest, SamplesEquirectangularPixelsBilinearly) {
  // 4 x 2 pixels: longitude -180..180 in 4 columns, each 90 degrees wide;
  // values 100 * column + 10 * row.
  auto file = temp_file("map.exr");
  write_map(file, 4, 2, {0, 100, 200, 300, 10, 110, 210, 310});
  HeightMap map(file, 2.0, 5.0);
  auto dir = [](double lat_deg, double lon_deg) {
    double lat = glm::radians(lat_deg), lon = glm::radians(lon_deg);
    return glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  };
  // Pixel (1, 0)'s centre: longitude -45, latitude 45.
  EXPECT_NEAR(map.height(dir(45.0, -45.0)), 2.0 * 100 + 5.0, 1e-6);
  // Halfway between the centres of columns 1 and 2 on row 1.
  EXPECT_NEAR(map.height(dir(-45.0, 0.0)), 2.0 * 160 + 5.0, 1e-6);
  EXPECT_NEAR(map.range().min, 5.0, 1e-9);
  EXPECT_NEAR(map.range().max, 625.0, 1e-9);
}

TEST(HeightMapTest, BadFilesGiveErrorsNamingTheFile) {
  expect_error_naming(temp_file("does_not_exist.exr"), "a missing file");
  auto empty = temp_file("empty.exr");
  std::ofstream(empty).close();
  expect_error_naming(empty, "an empty file");
  auto junk = temp_file("junk.png");
  std::ofstream(junk) << "not an image at all";
  expect_error_naming(junk, "a file that is not an image");
  auto nan = temp_file("nan.exr");
  write_map(nan, 4, 2, {0, 1, 2, std::nanf(""), 4, 5, 6, 7});
  expect_error_naming(nan, "a NaN height");
  auto tiny = temp_file("tiny.exr");
  write_map(tiny, 1, 1, {3});
  expect_error_naming(tiny, "a single pixel");
  // A header of a few bytes that declares 16 x 8e30 pixels: refused before
  // anything is allocated for them.
  auto huge = temp_file("huge.pgm");
  std::ofstream(huge, std::ios::binary) << "P5\n16 8000000000000000000000000000000\n255\n"
                                        << std::string(64, '\xff');
  expect_error_naming(huge, "a header that declares more pixels than the program reads");
  try {
    HeightMap map(huge, 1.0, 0.0);
  } catch (const InputError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("16x2147483647 pixels and 1 channels is larger than the 134217728 values"),
              std::string::npos)
        << what;
  }
}

TEST(TerrainConfigTest, ErrorsNameTheBodyFileAndField) {
  Body body;
  body.name = "Test";
  body.file = "bodies/test.json";
  body.shape.equatorial_radius = 1e6;
  body.terrain = nlohmann::json::parse(
      R"({"height": {"type": "procedural", "layers": [{"type": "wavy", "amplitude_m": 1,
          "wavelength_m": 10, "octaves": 2}]}})");
  try {
    parse_terrain(body);
    FAIL() << "unknown layer type accepted";
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("bodies/test.json"), std::string::npos) << m;
    EXPECT_NE(m.find("wavy"), std::string::npos) << m;
  }
  body.terrain = nlohmann::json::parse(
      R"({"height": {"type": "height_map", "file": "/nonexistent/heights.exr", "scale_m": 1}})");
  try {
    parse_terrain(body);
    FAIL() << "missing height map accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/heights.exr"), std::string::npos);
  }
}

// The wind that shapes the sea's glint: Cox and Munk's fit holds to
// 15 m/s; beyond, one error naming the file and the key.
TEST(TerrainConfigTest, SeaWindIsReadAndOutOfRangeNamesFileAndKey) {
  Body body;
  body.name = "Test";
  body.file = "bodies/test.json";
  body.shape.equatorial_radius = 1e6;
  const char* heights = R"("height": {"type": "procedural", "layers": [], "sea_level_m": 0})";
  body.terrain =
      nlohmann::json::parse(fmt::format(R"({{{}, "sea": {{"wind_m_s": 2.5}}}})", heights));
  EXPECT_EQ(parse_terrain(body).sea_wind, 2.5);
  body.terrain = nlohmann::json::parse(fmt::format("{{{}}}", heights));
  EXPECT_EQ(parse_terrain(body).sea_wind, 7.0);
  for (const char* wind : {"-1", "40", "\"calm\""}) {
    body.terrain =
        nlohmann::json::parse(fmt::format(R"({{{}, "sea": {{"wind_m_s": {}}}}})", heights, wind));
    try {
      parse_terrain(body);
      FAIL() << "wind " << wind << " accepted";
    } catch (const InputError& e) {
      std::string m = e.what();
      EXPECT_NE(m.find("bodies/test.json"), std::string::npos) << m;
      EXPECT_NE(m.find("wind_m_s"), std::string::npos) << m;
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
