// The sun's glint on the open sea (terrain/shaders/sea_brdf.glsl) as the
// terrain pass draws it, against the same BRDF integrated in double over
// the sun's disk and each pixel, and its width against the wind.
#include "terrain/gpu/terrain_renderer.h"
#include "terrain/sea_brdf.h"
#include "tests/terrain/terrain_target.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "core/image_io.h"
#include "gl/context.h"
#include "sim/geodesy.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// A column of pixels down the middle of the view holds the glint: the sun
// stands in the camera's heading. Odd width: the middle column's centre
// lies on the view's plane of symmetry.
constexpr int kWidth = 33, kHeight = 96;
constexpr double kFovDeg = 90.0;
constexpr double kSunRadius = 0.00465;  // the sun's angular radius, radians

// An airless sphere the size of the Earth, all of it open sea 1 km deep
// with nothing coming up from below it (black water): the terrain pass
// then draws the glint alone, lit by the unit irradiance at the top.
Body sea_body(double wind_m_s) {
  Body body;
  body.name = "Sea";
  body.file = "sea_glint_gl_test.json";
  body.shape.equatorial_radius = 6378137.0;
  body.terrain = nlohmann::json::parse(fmt::format(R"({{
      "max_level": 14,
      "height": {{"type": "procedural", "layers": [], "offset_m": -1000, "sea_level_m": 0}},
      "albedo": {{"low": [0.1, 0.1, 0.1], "high": [0.2, 0.2, 0.2], "steep": [0.3, 0.3, 0.3],
                  "ocean": [0, 0, 0]}},
      "sea": {{"wind_m_s": {}}}}})",
                                                   wind_m_s));
  return body;
}

struct View {
  Camera camera;
  glm::dvec3 sun{0, 0, 1};
};

// 400 km over the equator looking north 55 degrees down, the sun 50
// degrees up in the north: the glint's centre lies some 280 km ahead, 35
// degrees from the nadir.
View glint_view(const Body& body) {
  Geodesy geodesy(body.shape);
  Geodetic place{0.0, 0.0, 400e3};
  View v;
  v.camera = geodesy.camera_at(place, 0.0, glm::radians(-55.0), glm::radians(kFovDeg));
  v.camera.near = 10.0;
  v.sun = geodesy.body_direction(Geodetic{0.0, 0.0, 0.0}, glm::radians(50.0), 0.0);
  return v;
}

// The direction through a point of the image, (x, y) in pixels from the
// lower left corner.
glm::dvec3 ray_body(const Camera& camera, double x, double y) {
  glm::dmat3 ray_from_ndc = view_ray_from_ndc(camera.vertical_fov, double(kWidth) / kHeight);
  glm::dvec3 view = ray_from_ndc * glm::dvec3(2.0 * x / kWidth - 1.0, 2.0 * y / kHeight - 1.0, 1.0);
  return glm::normalize(camera.body_from_camera * view);
}

// The glint's radiance in the middle column's pixel `row` (from the
// bottom) per unit of the sun's irradiance: sea_glint averaged over 8 x 8
// points of the pixel, each over the sun's disk of uniform radiance (a
// point at its centre and 6 rings of 12, by equal areas), where the ray
// meets the sea's sphere.
double reference_glint(const Body& body, const View& v, int row, double sigma2) {
  const double radius = body.shape.equatorial_radius;
  glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), v.sun));
  glm::dvec3 north = glm::cross(v.sun, east);
  double sum = 0.0;
  int samples = 0;
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      glm::dvec3 dir = ray_body(v.camera, kWidth / 2 + (i + 0.5) / 8.0, row + (j + 0.5) / 8.0);
      // The nearer root of |pos + t dir| = radius.
      double b = glm::dot(v.camera.pos_body, dir);
      double c = glm::dot(v.camera.pos_body, v.camera.pos_body) - radius * radius;
      double disc = b * b - c;
      if (disc < 0.0) continue;  // past the horizon: counted as dark
      glm::dvec3 p = v.camera.pos_body + (-b - std::sqrt(disc)) * dir;
      glm::dvec3 n = glm::normalize(p);
      double disk = sea::sea_glint(n, -dir, v.sun, sigma2);
      int points = 1;
      for (int ring = 0; ring < 6; ++ring) {
        double r = kSunRadius * std::sqrt((ring + 0.5) / 6.0);
        for (int k = 0; k < 12; ++k) {
          double a = 2.0 * glm::pi<double>() * (k + 0.5 * (ring % 2)) / 12.0;
          glm::dvec3 sun = glm::normalize(v.sun + r * (std::cos(a) * east + std::sin(a) * north));
          disk += sea::sea_glint(n, -dir, sun, sigma2);
          ++points;
        }
      }
      // Centre weight 1 of 73 against its area share of 1/73: equal.
      sum += disk / points;
      ++samples;
    }
  }
  return sum / 64.0;
}

class SeaGlintGLTest : public ::testing::Test {
 protected:

  // The middle column's radiance (red), from the bottom row up; the image
  // written to the test's folder for a person to look at.
  std::vector<double> draw_column(const Body& body, const View& v, const std::string& name) {
    TerrainRenderer terrain(body, TerrainOptions{});
    terrain.wait_until_complete(v.camera, kWidth, kHeight, 120.0);
    const float black[4] = {0, 0, 0, 1};
    std::vector<float> rgba = target_.draw(terrain, v.camera, v.sun, black);
    std::vector<uint8_t> ldr(size_t(kWidth) * kHeight * 3);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        for (int c = 0; c < 3; ++c) {
          float value = rgba[(size_t(kHeight - 1 - y) * kWidth + x) * 4 + c];
          ldr[(size_t(y) * kWidth + x) * 3 + c] =
              uint8_t(std::clamp(value / 3.0f, 0.0f, 1.0f) * 255.0f + 0.5f);
        }
      }
    }
    std::filesystem::path out = std::filesystem::temp_directory_path() / "planet_sea_glint";
    std::filesystem::create_directories(out);
    write_png_rgb8(out / (name + ".png"), kWidth, kHeight, ldr);
    std::vector<double> column(kHeight);
    for (int y = 0; y < kHeight; ++y) column[y] = rgba[(size_t(y) * kWidth + kWidth / 2) * 4];
    return column;
  }

  TerrainTarget target_{kWidth, kHeight};
};

TEST_F(SeaGlintGLTest, GlintAlongALineMatchesTheBrdfIntegratedOverSunAndPixel) {
  const double wind = 7.0;
  Body body = sea_body(wind);
  View v = glint_view(body);
  std::vector<double> gpu = draw_column(body, v, "glint_7");
  const double sigma2 = sea::cox_munk_slope_variance(wind);
  std::vector<double> cpu(kHeight);
  for (int y = 0; y < kHeight; ++y) cpu[y] = reference_glint(body, v, y, sigma2);
  const double peak = *std::max_element(cpu.begin(), cpu.end());
  ASSERT_GT(peak, 0.01) << "no glint in view";
  // Every pixel of the line where the glint is over a twentieth of its
  // peak, within 2 % (the pixel's and the disk's extent change the
  // radiance by under 0.1 % at this wind; float and the mesh's facets
  // leave less).
  double worst = 0.0;
  int compared = 0;
  for (int y = 0; y < kHeight; ++y) {
    if (cpu[y] < 0.05 * peak) continue;
    ++compared;
    double error = std::abs(gpu[y] / cpu[y] - 1.0);
    worst = std::max(worst, error);
    EXPECT_LT(error, 0.02) << "row " << y << ": GPU " << gpu[y] << ", CPU " << cpu[y];
  }
  EXPECT_GT(compared, 10);
  std::printf("glint: peak %.4f, %d pixels compared, worst relative error %.5f\n", peak, compared,
              worst);
}

// The full width at half maximum of the glint along the column, as the
// angle between the rays through the two half-maximum points (linear
// between pixel centres).
double glint_width(const Camera& camera, const std::vector<double>& column) {
  int top = int(std::max_element(column.begin(), column.end()) - column.begin());
  double half = 0.5 * column[top];
  auto crossing = [&](int step) {
    int y = top;
    while (y + step >= 0 && y + step < kHeight && column[y + step] > half) y += step;
    if (y + step < 0 || y + step >= kHeight) return std::nan("");
    double f = (column[y] - half) / (column[y] - column[y + step]);
    return y + step * f + 0.5;
  };
  double below = crossing(-1), above = crossing(+1);
  return std::acos(glm::dot(ray_body(camera, kWidth / 2 + 0.5, below),
                            ray_body(camera, kWidth / 2 + 0.5, above)));
}

TEST_F(SeaGlintGLTest, GlintWidensWithTheWindAsCoxAndMunksSlopesSay) {
  double width[2], reference[2];
  const double winds[2] = {2.0, 10.0};
  for (int i = 0; i < 2; ++i) {
    Body body = sea_body(winds[i]);
    View v = glint_view(body);
    width[i] = glint_width(v.camera, draw_column(body, v, fmt::format("glint_{:.0f}", winds[i])));
    ASSERT_TRUE(std::isfinite(width[i])) << "the glint at " << winds[i] << " m/s leaves the view";
    std::vector<double> cpu(kHeight);
    const double sigma2 = sea::cox_munk_slope_variance(winds[i]);
    for (int y = 0; y < kHeight; ++y) cpu[y] = reference_glint(body, v, y, sigma2);
    reference[i] = glint_width(v.camera, cpu);
  }
  const double expected =
      std::sqrt(sea::cox_munk_slope_variance(winds[1]) / sea::cox_munk_slope_variance(winds[0]));
  const double ratio = width[1] / width[0];
  std::printf(
      "glint FWHM %.3f deg at 2 m/s, %.3f deg at 10 m/s (CPU %.3f, %.3f): ratio %.4f, "
      "CPU %.4f, sqrt(sigma2 ratio) %.4f\n",
      glm::degrees(width[0]), glm::degrees(width[1]), glm::degrees(reference[0]),
      glm::degrees(reference[1]), ratio, reference[1] / reference[0], expected);
  // The width in the view follows the slopes' spread but for the view's
  // geometry: the facets' tilt is half the view's turn only for small
  // slopes, and 1 / cos(view) and the Earth's curvature lift the glint's
  // far side. The integrated BRDF's own ratio comes out 6.3 % above
  // sqrt(sigma2 ratio) in this view: 10 % holds it, and the GPU's ratio
  // keeps to the CPU's within 1 %.
  EXPECT_NEAR(ratio / expected, 1.0, 0.1);
  EXPECT_NEAR(ratio / (reference[1] / reference[0]), 1.0, 0.01);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
