// The terrain's shadows as a frame shows them: at a low sun the ridges
// shade a part of the ground (measured: 374 of 4926 ground pixels lose a
// tenth or more), at a high sun none, and shadows only ever take light
// away.
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

namespace planet {
namespace {

constexpr int kWidth = 128, kHeight = 64;

struct Frame {
  std::vector<float> hdr, distance;
};

Frame render(const Body& body, const PlaceView& view, bool shadows) {
  FrameRenderer renderer(kWidth, kHeight);
  renderer.set_terrain_shadows(shadows);
  renderer.set_body(body, load_atmosphere(body), make_technique("hillaire"));
  renderer.render(view.camera, view.sun_dir_body, 10.0);
  return {renderer.read_hdr(), renderer.read_distance(view.camera)};
}

struct Shade {
  int ground = 0;    // pixels with a surface
  int darker = 0;    // of those, below 0.9 of their radiance without shadows
  int brighter = 0;  // above it by more than float rounding
};

Shade compare(const Body& body, const PlaceView& view) {
  Frame on = render(body, view, true), off = render(body, view, false);
  Shade s;
  for (size_t p = 0; p < size_t(kWidth * kHeight); ++p) {
    if (!std::isfinite(off.distance[p])) continue;  // open sky
    float a = 0, b = 0;
    for (int c = 0; c < 3; ++c) {
      a += off.hdr[p * 4 + c];
      b += on.hdr[p * 4 + c];
    }
    ++s.ground;
    s.darker += b < 0.9f * a;
    s.brighter += b > a * (1.0f + 1e-5f);
  }
  return s;
}

TEST(TerrainShadowsGLTest, LowSunShadesTheValleysAndHighSunAlmostNothing) {
  auto context = GlContext::create_headless();
  Body earth = load_body(data_dir() / "planets" / "earth.json");
  // alps_sunset's frame 20: 3000 m over the Alps, looking away from a sun
  // 3 deg up in the west-north-west; then the same sun 60 deg up.
  Geodetic place{glm::radians(46.52), glm::radians(7.95), 3000.0};
  Shade low = compare(earth, view_from_place(earth.shape, place, 100.0, -8.0, 60.0, 3.0, 300.0));
  Shade high = compare(earth, view_from_place(earth.shape, place, 100.0, -8.0, 60.0, 60.0, 300.0));
  std::printf("sun 3 deg: %d of %d pixels darker by a tenth or more; sun 60 deg: %d of %d\n",
              low.darker, low.ground, high.darker, high.ground);
  EXPECT_GT(low.ground, kWidth * kHeight / 2);
  EXPECT_GT(low.darker, low.ground / 20);
  EXPECT_LT(high.darker, high.ground / 200);
  EXPECT_EQ(low.brighter, 0);
  EXPECT_EQ(high.brighter, 0);
}

}  // namespace
}  // namespace planet
