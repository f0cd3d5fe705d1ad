// The glare: off unless asked; on, the sun spreads its light around it as
// an eye's glare does, and a view without it keeps its look.
#include "atmosphere/atmosphere_inputs.h"
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tests/render/view_from_place.h"
#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 128, kHeight = 64;

struct Frame {
  std::vector<float> hdr;
  std::vector<uint8_t> ldr;
  bool glare_pass = false;
};

// Over the Alps in the afternoon, 6 km up, the sun 20 degrees up in the
// south-west, seen through `fov_deg` along `heading_deg` and `pitch_deg`.
Frame render(bool glare, double heading_deg, double pitch_deg, double fov_deg,
             double exposure = 8.0) {
  // The procedural Earth, over which the glare's bounds were measured.
  Body body = load_body(project_root() / "tests/data/planets/earth_procedural.json");
  PlaceView view = view_from_place(body.shape, {glm::radians(46.55), glm::radians(7.98), 6000.0},
                                   heading_deg, pitch_deg, fov_deg, 20.0, 240.0);
  FrameRenderer renderer(kWidth, kHeight);
  FrameOptions options;
  options.antialiasing = 4;
  options.glare = glare;
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body), make_technique("hillaire"));
  FrameStats stats = renderer.render(view.camera, view.sun_dir_body, exposure);
  Frame f{renderer.read_hdr(), renderer.read_ldr(), false};
  for (const auto& p : stats.passes) f.glare_pass = f.glare_pass || (p.pass == "glare" && p.ran());
  return f;
}

double mean_ldr(const Frame& f, int x, int y) {
  const size_t i = (size_t(y) * kWidth + size_t(x)) * 4;
  return (f.ldr[i] + f.ldr[i + 1] + f.ldr[i + 2]) / 3.0;
}

// A narrow view (10 degrees: the sun is 3 pixels wide, not missed between
// pixels' centres), exposed for the glare (at fly's 8 it whitens the sky
// for 6 degrees around the sun, as the glare equation says).
TEST(GlareGLTest, TheSunGlares) {
  auto context = GlContext::create_headless();
  Frame off = render(false, 240.0, 18.0, 10.0, 1.0), on = render(true, 240.0, 18.0, 10.0, 1.0);
  EXPECT_FALSE(off.glare_pass) << "glare is off unless asked";
  EXPECT_TRUE(on.glare_pass);
  EXPECT_EQ(off.hdr, on.hdr) << "the glare is the eye's: the radiance stays the scene's";
  // The sun: the brightest pixel of the radiance.
  size_t sun = 0;
  for (size_t p = 0; p < size_t(kWidth * kHeight); ++p) {
    if (off.hdr[p * 4 + 1] > off.hdr[sun * 4 + 1]) sun = p;
  }
  const int sx = int(sun % kWidth), sy = int(sun / kWidth);
  std::printf("the sun's pixel (%d, %d): %.3g\n", sx, sy, double(off.hdr[sun * 4 + 1]));
  ASSERT_GT(off.hdr[sun * 4 + 1], 100.0f) << "the sun is not in view";
  ASSERT_GT(sx, 12);
  ASSERT_LT(sx, kWidth - 12);
  ASSERT_GT(sy, 12);
  ASSERT_LT(sy, kHeight - 12);
  // Beside the sun, 12 and 40 pixels (1.9 and 6.2 degrees) to its left and
  // right: brighter by the glare, the nearer the more.
  auto gain = [&](int dx) {
    return 0.5 * (mean_ldr(on, sx - dx, sy) - mean_ldr(off, sx - dx, sy) +
                  mean_ldr(on, sx + dx, sy) - mean_ldr(off, sx + dx, sy));
  };
  ASSERT_GE(sx, 40);
  ASSERT_LT(sx, kWidth - 40);
  const double near_gain = gain(12), far_gain = gain(40);
  std::printf("glare adds %.1f display levels 1.9 deg from the sun, %.1f at 6.2 deg\n", near_gain,
              far_gain);
  EXPECT_GT(near_gain, 10.0) << "no glare around the sun";
  EXPECT_GT(near_gain, far_gain) << "the glare does not fall off away from the sun";
}

// With the sun behind the camera nothing is bright enough to glare: what
// the glare takes from each pixel it gives back around it.
TEST(GlareGLTest, AViewWithoutTheSunKeepsItsLook) {
  auto context = GlContext::create_headless();
  Frame off = render(false, 60.0, 0.0, 60.0), on = render(true, 60.0, 0.0, 60.0);
  double sum = 0, most = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      double d = std::abs(mean_ldr(on, x, y) - mean_ldr(off, x, y));
      sum += d;
      most = std::max(most, d);
    }
  }
  const double mean = sum / (kWidth * kHeight);
  std::printf("glare changed the display values by %.2f levels on average, %.1f at most\n", mean,
              most);
  EXPECT_LT(mean, 1.5);
  EXPECT_LT(most, 8.0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
