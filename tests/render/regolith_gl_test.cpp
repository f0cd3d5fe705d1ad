// Regolith as a frame shows it: the full Moon stays bright to its limb,
// where Lambert's law darkens it to nothing, and at a low sun on the Moon
// the ground in the shadow of Tycho's walls is black: the Moon has no sky,
// and neither the light its lit ground reflects into the shadows nor the
// earthshine is modelled.
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::vector<float> render_hdr(const Body& body, const Camera& camera, const glm::dvec3& sun,
                              int width, int height, bool shadows = true) {
  FrameRenderer renderer(width, height);
  FrameOptions options;
  options.terrain_shadows = shadows;
  renderer.set_options(options);
  renderer.set_body(body, std::nullopt, nullptr);
  renderer.render(camera, sun, 1.0);
  return renderer.read_hdr();
}

float luminance(const std::vector<float>& hdr, size_t p) {
  return 0.2126f * hdr[4 * p] + 0.7152f * hdr[4 * p + 1] + 0.0722f * hdr[4 * p + 2];
}

// The Moon smooth and of one albedo, so that the frame shows the law alone.
Body smooth_grey_moon(bool regolith) {
  Body moon = load_body(data_dir() / "planets" / "moon.json");
  moon.terrain["height"] = {
      {"type", "procedural"},
      {"layers", {{{"type", "fbm"}, {"amplitude_m", 0.0}, {"wavelength_m", 1e5}, {"octaves", 1}}}}};
  for (const char* key : {"low", "high", "steep"}) moon.terrain["albedo"][key] = {0.12, 0.12, 0.12};
  moon.terrain["albedo"].erase("craters");
  if (!regolith) moon.terrain.erase("regolith");
  return moon;
}

// The mean luminance of the full Moon's disk within rings of its apparent
// radius: [0, 0.2) and [0.85, 0.92).
struct Disk {
  double centre = 0, limb = 0;
};

Disk full_moon(bool regolith) {
  constexpr int kSize = 128;
  const Body moon = smooth_grey_moon(regolith);
  const double radius = moon.shape.equatorial_radius, distance = 60.0 * radius;  // Earth's
  Camera camera;
  camera.pos_body = glm::dvec3(distance, 0.0, 0.0);
  // Looking down -x, +z up: the camera's right, up and back in the body.
  camera.body_from_camera =
      glm::quat_cast(glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0)));
  camera.vertical_fov = glm::radians(2.4);
  camera.near = 1000.0;
  // The sun behind the camera: phase 0 at the disk's centre.
  std::vector<float> hdr = render_hdr(moon, camera, glm::dvec3(1, 0, 0), kSize, kSize);
  const double disk_px =
      std::tan(std::asin(radius / distance)) / std::tan(0.5 * camera.vertical_fov) * (0.5 * kSize);
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double rho = std::hypot(x + 0.5 - 0.5 * kSize, y + 0.5 - 0.5 * kSize) / disk_px;
      int ring = rho < 0.2 ? 0 : (rho >= 0.85 && rho < 0.92) ? 1 : -1;
      if (ring < 0) continue;
      sum[ring] += luminance(hdr, size_t(y) * kSize + size_t(x));
      ++count[ring];
    }
  }
  return {sum[0] / count[0], sum[1] / count[1]};
}

TEST(RegolithGLTest, TheFullMoonStaysBrightToItsLimb) {
  auto context = GlContext::create_headless();
  Disk hapke = full_moon(true), lambert = full_moon(false);
  std::printf(
      "full Moon, limb (0.85-0.92 of the radius) over centre: regolith %.3f, Lambert %.3f\n",
      hapke.limb / hapke.centre, lambert.limb / lambert.centre);
  // Lambert's: the ring's mean cos(t), about 0.45 (0.39 to 0.53). The
  // law's stays near 1, less the opposition surge's fall over the ring's
  // phase angles (up to 1 deg from 60 radii).
  EXPECT_GT(hapke.limb / hapke.centre, 0.8);
  EXPECT_LT(lambert.limb / lambert.centre, 0.6);
  EXPECT_GT(hapke.centre, 0.0);
}

TEST(RegolithGLTest, TychosShadowsAreBlackAtALowSun) {
  auto context = GlContext::create_headless();
  constexpr int kWidth = 128, kHeight = 64;
  const Body moon = load_body(data_dir() / "planets" / "moon.json");
  ASSERT_FALSE(moon.has_atmosphere());
  // 6 km over Tycho's floor (43.31 S, 11.36 W), looking west and down
  // across the crater, the sun 5 deg up in the east behind the camera:
  // about half the sunward ground lies in the shadows of the rim and the
  // relief.
  Geodetic place{glm::radians(-43.31), glm::radians(-11.36), 0.0};
  place.height = terrain_ground()(moon, place) + 6000.0;
  PlaceView view = view_from_place(moon.shape, place, 270.0, -30.0, 60.0, 5.0, 95.0);
  std::vector<float> on = render_hdr(moon, view.camera, view.sun_dir_body, kWidth, kHeight, true);
  std::vector<float> off = render_hdr(moon, view.camera, view.sun_dir_body, kWidth, kHeight, false);
  std::vector<float> lit;
  int ground = 0, shadowed = 0, black = 0;
  float brightest_shadow = 0;
  for (size_t p = 0; p < size_t(kWidth * kHeight); ++p) {
    float a = luminance(off, p), b = luminance(on, p);
    if (a <= 0) continue;  // space, or ground the sun does not face
    ++ground;
    lit.push_back(a);
    if (b < 0.5f * a) {
      ++shadowed;
      brightest_shadow = std::max(brightest_shadow, b / a);
    }
  }
  ASSERT_GT(ground, 0);
  std::nth_element(lit.begin(), lit.begin() + long(lit.size() / 2), lit.end());
  const float median = lit[lit.size() / 2];
  for (size_t p = 0; p < size_t(kWidth * kHeight); ++p) {
    float a = luminance(off, p), b = luminance(on, p);
    if (a > 0 && b < 0.5f * a && b <= 1e-6f * median) ++black;
  }
  std::printf(
      "sun 5 deg up over Tycho: %d of %d sunward ground pixels shadowed (under half their "
      "light), %d of them black (under 1e-6 of the median lit pixel); the brightest shadowed "
      "pixel keeps %.3f of its light\n",
      shadowed, ground, black, brightest_shadow);
  // The long shadows are there to see...
  EXPECT_GT(shadowed, ground / 20);
  // ...and black but for their soft edge (the sun's disc, a few pixels).
  EXPECT_GT(black, shadowed * 8 / 10);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
