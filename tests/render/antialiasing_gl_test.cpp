// Anti-aliased edges of the ground against the sky and space: a frame with
// 4 samples a pixel against the same frame drawn at 4 times the size and
// averaged down in linear radiance (16 rays a pixel), over the pixels the
// edge crosses; and frames that stay the same run to run.
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 96, kHeight = 48, kScale = 4;

struct Frame {
  std::vector<float> hdr, distance;
};

Frame render(const Body& body, const PlaceView& view, int width, int height, int samples,
             double pixel_budget) {
  FrameRenderer renderer(width, height);
  FrameOptions options;
  options.antialiasing = samples;
  // The same tiles at every size: their error is counted in pixels.
  options.terrain.pixel_budget = pixel_budget;
  renderer.set_options(options);
  if (body.has_atmosphere()) {
    renderer.set_body(body, load_atmosphere(body), make_technique("hillaire"));
  } else {
    renderer.set_body(body, std::nullopt, nullptr);
  }
  renderer.render(view.camera, view.sun_dir_body, 10.0);
  return {renderer.read_hdr(), renderer.read_distance(view.camera)};
}

float luminance(const std::vector<float>& hdr, size_t pixel) {
  return 0.2126f * hdr[pixel * 4] + 0.7152f * hdr[pixel * 4 + 1] + 0.0722f * hdr[pixel * 4 + 2];
}

struct EdgeError {
  int pixels = 0;
  double one_sample = 0, four_samples = 0;  // RMS of luminance, relative to the reference's
};

// Over the pixels whose kScale x kScale block in the large frame holds both
// open sky and ground: the RMS relative error of the one- and four-sample
// frames against the block's mean.
EdgeError edge_error(const Body& body, const PlaceView& view) {
  Frame large = render(body, view, kWidth * kScale, kHeight * kScale, 1, kScale);
  Frame one = render(body, view, kWidth, kHeight, 1, 1.0);
  Frame four = render(body, view, kWidth, kHeight, 4, 1.0);
  EdgeError e;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      double sum = 0;
      int open = 0;
      for (int j = 0; j < kScale; ++j) {
        for (int i = 0; i < kScale; ++i) {
          size_t p = size_t(y * kScale + j) * size_t(kWidth * kScale) + size_t(x * kScale + i);
          sum += luminance(large.hdr, p);
          open += std::isinf(large.distance[p]) ? 1 : 0;
        }
      }
      if (open == 0 || open == kScale * kScale) continue;
      double reference = sum / (kScale * kScale);
      size_t p = size_t(y) * kWidth + size_t(x);
      double a = (luminance(one.hdr, p) - reference) / reference;
      double b = (luminance(four.hdr, p) - reference) / reference;
      e.one_sample += a * a;
      e.four_samples += b * b;
      ++e.pixels;
    }
  }
  if (e.pixels > 0) {
    e.one_sample = std::sqrt(e.one_sample / e.pixels);
    e.four_samples = std::sqrt(e.four_samples / e.pixels);
  }
  return e;
}

// The Alps' ridges against the sky from 2 m: along the edge, four samples
// a pixel must come at least twice as close to the 16-ray frame as one
// sample does (measured: 20.9 % against 8.2 %). Earth's limb from 400 km,
// where ground and glow differ little and the glow falls steeply above
// the limb: closer, if by less (16.7 % against 13.8 %).
TEST(AntialiasingGLTest, EdgesComeCloseToAFrameOfSixteenRaysAPixel) {
  auto context = GlContext::create_headless();
  // The procedural Earth, over which these figures were measured (the
  // elevation grid's Alps: the next test).
  Body earth = load_body(project_root() / "tests/data/planets/earth_procedural.json");
  struct Case {
    const char* name;
    Geodetic place;
    double pitch_deg, fov_deg;
    double most;  // of the one-sample error
  };
  // 2 m over the Alps' ground.
  Geodetic alps{glm::radians(46.5), glm::radians(8.0), 0.0};
  alps.height = ground_height(TerrainSurface(earth.shape, parse_terrain(earth)),
                              Geodesy(earth.shape), alps) + 2.0;
  for (const Case& c : {Case{"alps from 2 m", alps, 8.0, 60.0, 0.5},
                        Case{"limb from 400 km", {glm::radians(46.5), glm::radians(8.0), 400e3},
                             -18.0, 50.0, 0.9}}) {
    auto view = view_from_place(earth.shape, c.place, 30.0, c.pitch_deg, c.fov_deg, 25.0, 150.0);
    EdgeError e = edge_error(earth, view);
    std::printf("%s: %d edge pixels; luminance error against 16 rays a pixel: %.1f %% with one "
                "sample, %.1f %% with four\n",
                c.name, e.pixels, 100.0 * e.one_sample, 100.0 * e.four_samples);
    EXPECT_GT(e.pixels, kWidth / 2) << c.name << ": the view shows too little edge";
    EXPECT_LT(e.four_samples, c.most * e.one_sample) << c.name;
  }
}

// The same edge over ETOPO5's Alps, whose smooth slopes' silhouettes are
// triangles seen edge-on: a pixel whose centre misses such a triangle took
// its values extrapolated far outside it (albedo 24; the edge pixel 3.37
// against 0.18 from 16 rays, and the edge's error 227.9 % with four
// samples against 24.3 % with one), until terrain.frag held them to what
// they can be (measured since: 14.0 % with four). Those pixels keep the
// triangle's values held at their bounds, so the edge comes closer than
// with one sample, if not twice as close as over the procedural ridges.
TEST(AntialiasingGLTest, TheAlpsEdgeOverTheElevationGridHasNoBrightPixel) {
  auto context = GlContext::create_headless();
  Body earth = load_body(data_dir() / "planets" / "earth.json");
  Geodetic alps{glm::radians(46.5), glm::radians(8.0), 0.0};
  alps.height = terrain_ground()(earth, alps) + 2.0;
  auto view = view_from_place(earth.shape, alps, 30.0, 8.0, 60.0, 25.0, 150.0);
  EdgeError e = edge_error(earth, view);
  std::printf(
      "ETOPO5's alps from 2 m: %d edge pixels; %.1f %% with one sample, %.1f %% with four\n",
      e.pixels, 100.0 * e.one_sample, 100.0 * e.four_samples);
  EXPECT_GT(e.pixels, kWidth / 2);
  EXPECT_LT(e.four_samples, 0.75 * e.one_sample);
}

// The Moon's limb against black space from 100 km: its surfaces are the
// image, and an edge pixel is its coverage times the ground (measured:
// 80.1 % with one sample, 37.3 % with four: relative to edge pixels that
// are mostly black, where a sixteenth of coverage is much of the value).
TEST(AntialiasingGLTest, TheMoonsLimbAgainstSpace) {
  auto context = GlContext::create_headless();
  // The procedural Moon, over which these figures were measured (over LOLA's
  // grid: 80.7 % with one sample, 92.9 % with four: not yet understood).
  Body moon = load_body(project_root() / "tests/data/planets/moon_procedural.json");
  auto view = view_from_place(moon.shape, {glm::radians(10.0), glm::radians(20.0), 100e3}, 90.0,
                              -8.0, 50.0, 20.0, 120.0);
  EdgeError e = edge_error(moon, view);
  std::printf("moon's limb from 100 km: %d edge pixels; %.1f %% with one sample, %.1f %% with four\n",
              e.pixels, 100.0 * e.one_sample, 100.0 * e.four_samples);
  EXPECT_GT(e.pixels, kWidth / 2);
  EXPECT_LT(e.four_samples, 0.5 * e.one_sample);
}

TEST(AntialiasingGLTest, FramesAreTheSameRunToRun) {
  auto context = GlContext::create_headless();
  Body earth = load_body(data_dir() / "planets" / "earth.json");
  Geodetic alps{glm::radians(46.5), glm::radians(8.0), 0.0};
  alps.height = ground_height(TerrainSurface(earth.shape, parse_terrain(earth)),
                              Geodesy(earth.shape), alps) + 2.0;
  auto view = view_from_place(earth.shape, alps, 30.0, 8.0, 60.0, 25.0, 150.0);
  Frame a = render(earth, view, kWidth, kHeight, 4, 1.0);
  Frame b = render(earth, view, kWidth, kHeight, 4, 1.0);
  EXPECT_EQ(a.hdr, b.hdr);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
