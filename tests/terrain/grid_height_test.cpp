// The elevation grid height source on small grids made here: it honours
// its samples, its slope has no kinks, it wraps in longitude and has one
// value at each pole, its bounds hold, and bad grids and datums are
// refused in one line naming the file.
#include "terrain/grid_height.h"
#include "terrain/terrain_config.h"

#include "core/error.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// A folder of this process's own: CTest runs the cases at once, each a process.
std::filesystem::path temp_file(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("planet_grid_height_test-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

glm::dvec3 dir_at(double lat_deg, double lon_deg) {
  double lat = glm::radians(lat_deg), lon = glm::radians(lon_deg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// A raw little-endian grid of codes, row-major from the north.
void write_raw(const std::filesystem::path& file, const std::vector<int16_t>& codes,
               bool big_endian = false) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  for (int16_t c : codes) {
    auto u = uint16_t(c);
    unsigned char b[2] = {static_cast<unsigned char>(u & 0xff), static_cast<unsigned char>(u >> 8)};
    if (big_endian) std::swap(b[0], b[1]);
    out.write(reinterpret_cast<const char*>(b), 2);
  }
}

// An 8 x 4 pixel grid (45 x 45 degree cells from 0 E) of smooth but
// uneven values, in metres.
std::vector<int16_t> test_codes(int w = 8, int h = 4) {
  std::vector<int16_t> codes;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      codes.push_back(int16_t(100 * i - 30 * j * j + 7 * ((i * 3 + j) % 5)));
  return codes;
}

GridSpec pixel_spec(const std::filesystem::path& file, int w = 8, int h = 4) {
  GridSpec s;
  s.file = file;
  s.layout = GridSpec::Layout::kInt16Le;
  s.registration = GridSpec::Registration::kPixel;
  s.width = w;
  s.height = h;
  return s;
}

GridHeight test_grid(const std::string& name = "grid.img") {
  auto file = temp_file(name);
  write_raw(file, test_codes());
  return GridHeight(std::make_shared<GridData>(pixel_spec(file)), 1e6, 1.0, std::nullopt);
}

TEST(GridHeightTest, PassesThroughEverySampleAwayFromThePoles) {
  GridHeight g = test_grid();
  auto codes = test_codes();
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 8; ++i) {
      double lat = 90.0 - (j + 0.5) * 45.0, lon = (i + 0.5) * 45.0;
      // Rows 0 and 3 lie half a row from a pole: blended into its value.
      if (j == 0 || j == 3) continue;
      EXPECT_NEAR(g.height(dir_at(lat, lon)), codes[size_t(j * 8 + i)], 1e-6) << i << "," << j;
      EXPECT_EQ(g.nearest_sample(dir_at(lat + 10, lon - 10)), codes[size_t(j * 8 + i)]);
    }
  }
}

TEST(GridHeightTest, SlopeHasNoKinkAtSampleColumnsOrRows) {
  // C1: the slope just west of a sample column equals the slope just east
  // of it, as it does across a sample row; bilinear interpolation fails
  // this by the difference of its neighbouring steps.
  GridHeight g = test_grid();
  const double e = 1e-4, d = 1e-7;  // degrees
  for (double lon : {45.0 * 2.5, 45.0 * 5.5}) {
    double lat = -22.5;
    double west = (g.height(dir_at(lat, lon - e)) - g.height(dir_at(lat, lon - e - d))) / d;
    double east = (g.height(dir_at(lat, lon + e + d)) - g.height(dir_at(lat, lon + e))) / d;
    EXPECT_NEAR(west, east, 1e-2 * (std::abs(west) + 1.0)) << "column at lon " << lon;
  }
  double lon = 100.0, lat = 22.5;  // row 1's centre
  double north = (g.height(dir_at(lat + e + d, lon)) - g.height(dir_at(lat + e, lon))) / d;
  double south = (g.height(dir_at(lat - e, lon)) - g.height(dir_at(lat - e - d, lon))) / d;
  EXPECT_NEAR(north, south, 1e-2 * (std::abs(north) + 1.0));
}

TEST(GridHeightTest, WrapsAcrossTheGridsWesternEdge) {
  GridHeight g = test_grid();
  for (double lat : {-30.0, 0.0, 40.0}) {
    double just_east = g.height(dir_at(lat, 1e-9)), just_west = g.height(dir_at(lat, -1e-9));
    EXPECT_NEAR(just_east, just_west, 1e-3) << lat;
    // And as smooth there as anywhere: the slope agrees on both sides.
    double d = 1e-6;
    double s_west = (just_west - g.height(dir_at(lat, -d))) / d;
    double s_east = (g.height(dir_at(lat, d)) - just_east) / d;
    EXPECT_NEAR(s_west, s_east, 1e-2 * (std::abs(s_west) + 1.0)) << lat;
  }
}

TEST(GridHeightTest, HasOneValueAtEachPoleAndReachesItSmoothly) {
  GridHeight g = test_grid();
  auto codes = test_codes();
  for (int pole = 0; pole < 2; ++pole) {
    double sign = pole == 0 ? 1.0 : -1.0;
    int row = pole == 0 ? 0 : 3;
    double mean = 0;
    for (int i = 0; i < 8; ++i) mean += codes[size_t(row * 8 + i)] / 8.0;
    for (double lon : {0.0, 33.0, 170.0, 260.0}) {
      EXPECT_NEAR(g.height(glm::dvec3(0, 0, sign)), mean, 1e-9);
      // Within a hair of the pole, any meridian gives nearly its value.
      EXPECT_NEAR(g.height(dir_at(sign * (90.0 - 1e-4), lon)), mean, 1.0) << lon;
    }
  }
}

TEST(GridHeightTest, RangeNearHoldsEveryHeightOfItsCap) {
  GridHeight g = test_grid();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    glm::dvec3 c = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    double radius = 1e6 * 0.05 * (1 + n % 20);  // 0.05 to 1 radian on a 1000 km body
    HeightRange r = g.range_near(c, radius);
    for (int k = 0; k < 50; ++k) {
      // A point of the cap: c turned by up to radius / R about a random axis.
      glm::dvec3 axis = glm::normalize(glm::cross(c, glm::dvec3(unit(rng), unit(rng), unit(rng))));
      double a = std::abs(unit(rng)) * radius / 1e6;
      glm::dvec3 p = c * std::cos(a) + glm::cross(axis, c) * std::sin(a);
      double h = g.height(p);
      EXPECT_GE(h, r.min - 1e-9);
      EXPECT_LE(h, r.max + 1e-9);
    }
    EXPECT_GE(r.min, g.range().min - 1e-9);
    EXPECT_LE(r.max, g.range().max + 1e-9);
  }
}

TEST(GridHeightTest, InterpolationErrorBoundsTheChordsMidpoints) {
  GridHeight g = test_grid();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double spacing : {1e3, 3e4, 3e5}) {
    double bound = g.interpolation_error(spacing);
    for (int n = 0; n < 300; ++n) {
      glm::dvec3 a = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
      glm::dvec3 axis = glm::normalize(glm::cross(a, glm::dvec3(unit(rng), unit(rng), unit(rng))));
      double t = spacing / 1e6;
      glm::dvec3 b = a * std::cos(t) + glm::cross(axis, a) * std::sin(t);
      glm::dvec3 m = glm::normalize(a + b);
      double off = std::abs(g.height(m) - 0.5 * (g.height(a) + g.height(b)));
      EXPECT_LE(off, bound) << spacing;
    }
  }
}

TEST(GridHeightTest, NodeRowsByGeodeticLatitudeAndBigEndianSamples) {
  // 8 x 5 nodes: rows at 90, 45, 0, -45, -90 degrees, columns every 45
  // from -180; a value of 1000 on the row at 45 N only.
  auto file = temp_file("node.img");
  std::vector<int16_t> codes(40, 0);
  for (int i = 0; i < 8; ++i) codes[size_t(8 + i)] = 1000;
  write_raw(file, codes, true);
  GridSpec s = pixel_spec(file, 8, 5);
  s.layout = GridSpec::Layout::kInt16Be;
  s.registration = GridSpec::Registration::kNode;
  s.west_longitude_deg = -180.0;
  s.geodetic_latitude = true;
  // An ellipsoid with (a/b)^2 = 1.1: the direction whose normal stands at
  // 45 degrees lies at atan(1 / 1.1) from the equator.
  GridHeight g(std::make_shared<GridData>(s), 1e6, 1.1, std::nullopt);
  double centric = glm::degrees(std::atan(1.0 / 1.1));
  EXPECT_NEAR(g.height(dir_at(centric, 10.0)), 1000.0, 1e-6);
  EXPECT_NEAR(g.height(dir_at(0.0, 10.0)), 0.0, 1e-6);
}

TEST(GridHeightTest, SeaLevelCoversTheSeaFloor) {
  auto file = temp_file("sea.img");
  write_raw(file, std::vector<int16_t>(32, -4000));
  GridHeight g(std::make_shared<GridData>(pixel_spec(file)), 1e6, 1.0, 0.0);
  EXPECT_EQ(g.height(dir_at(10, 10)), 0.0);
  EXPECT_NEAR(g.seabed_height(dir_at(10, 10)), -4000.0, 1e-9);
  EXPECT_EQ(g.range().min, 0.0);
}

// One InputError naming the file and saying what is wrong.
void expect_refused(const GridSpec& spec, const std::string& says) {
  try {
    GridData data(spec);
    FAIL() << "accepted; expected: " << says;
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find(spec.file.string()), std::string::npos) << m;
    EXPECT_NE(m.find(says), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(GridHeightTest, BadGridsAreRefusedNamingTheFileAndTheFault) {
  expect_refused(pixel_spec(temp_file("no_such_grid.img")), "no_such_grid.img");
  auto short_file = temp_file("short.img");
  auto codes = test_codes();
  codes.pop_back();
  write_raw(short_file, codes);
  expect_refused(pixel_spec(short_file),
                 "62 bytes, but a grid of 8 x 4 16-bit samples is 64 bytes (truncated?)");
  auto long_file = temp_file("long.img");
  write_raw(long_file, test_codes(8, 5));
  expect_refused(pixel_spec(long_file),
                 "80 bytes, but a grid of 8 x 4 16-bit samples is 64 bytes (not this grid?)");
  auto missing = temp_file("missing_value.img");
  codes = test_codes();
  codes[13] = -32768;  // PDS's missing-data value
  write_raw(missing, codes);
  expect_refused(pixel_spec(missing), "the sample at row 1, column 5 is -32768 m, not a height");
  // The right size but the wrong byte order: absurd heights.
  auto swapped = temp_file("swapped.img");
  write_raw(swapped, test_codes(), true);
  expect_refused(pixel_spec(swapped), "not a height");
  auto odd = pixel_spec(temp_file("grid.img"), 7, 4);
  expect_refused(odd, "a grid of 7 x 4 samples cannot be a global elevation grid");
  // A PNG of 8-bit samples, where 16 are declared.
  auto png8 = temp_file("eight_bit.png");
  {
    auto out = OIIO::ImageOutput::create(png8.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(8, 4, 1, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(png8.string(), spec));
    std::vector<uint8_t> v(32, 7);
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, v.data()));
    out->close();
  }
  GridSpec png = pixel_spec(png8);
  png.layout = GridSpec::Layout::kPngU16;
  expect_refused(png, "where the body's file declares 8 x 4 of one 16-bit channel");
  auto text = temp_file("text.png");
  std::ofstream(text) << "not an image";
  png.file = text;
  expect_refused(png, "text.png");
}

TEST(GridHeightTest, PngGridKeepsItsSixteenBits) {
  auto file = temp_file("grid16.png");
  auto codes = test_codes();
  {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(8, 4, 1, OIIO::TypeDesc::UINT16);
    ASSERT_TRUE(out->open(file.string(), spec));
    std::vector<uint16_t> v;
    for (int16_t c : codes) v.push_back(uint16_t(int(c) + 32768));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, v.data()));
    out->close();
  }
  GridSpec s = pixel_spec(file);
  s.layout = GridSpec::Layout::kPngU16;
  s.scale = 0.5;
  s.offset = -32768.0 * 0.5;
  GridData data(s);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 8; ++i) EXPECT_EQ(data.sample(i, j), 0.5 * codes[size_t(j * 8 + i)]);
}

TEST(TerrainConfigTest, GridDatumMustBeTheBodysOwn) {
  auto file = temp_file("body_grid.img");
  write_raw(file, test_codes());
  auto terrain = [&](const std::string& surface, double radius) {
    return nlohmann::json{{"height",
                           {{"type", "grid"},
                            {"file", file.string()},
                            {"layout", "int16_le"},
                            {"width", 8},
                            {"height", 4},
                            {"registration", "pixel"},
                            {"scale_m", 1.0},
                            {"latitude", "planetocentric"},
                            {"datum", {{"surface", surface}, {"radius_m", radius}}}}}};
  };
  Body body;
  body.name = "Test";
  body.file = "bodies/test.json";
  body.shape.equatorial_radius = 1737400.0;
  body.terrain = terrain("sphere", 1737400.0);
  EXPECT_NO_THROW(parse_terrain(body));
  auto refused = [&](const std::string& says) {
    try {
      parse_terrain(body);
      FAIL() << "accepted; expected: " << says;
    } catch (const InputError& e) {
      std::string m = e.what();
      EXPECT_NE(m.find("bodies/test.json"), std::string::npos) << m;
      EXPECT_NE(m.find(says), std::string::npos) << m;
    }
  };
  // Mars's areoid under a Moon-sized body: another body's grid.
  body.terrain = terrain("areoid", 3396000.0);
  refused("above the areoid of 3396000 m, which cannot stand for Test's ellipsoid of 1737400 m");
  // A sphere datum on a flattened body.
  body.shape.flattening = 0.01;
  body.terrain = terrain("sphere", 1737400.0);
  refused("above a sphere of 1737400 m, but Test is an ellipsoid");
  body.terrain = terrain("ellipsoid", 1737400.0);
  refused("'ellipsoid' is not a datum (sphere, geoid, areoid)");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
