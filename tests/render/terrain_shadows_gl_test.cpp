// The terrain's shadows as a frame shows them: at a low sun the ridges
// shade a part of the ground and the air over it (measured over ETOPO5's
// Alps: 1033 of 4806 ground pixels lose a tenth or more), at a high sun
// none, and shadows only ever take light away; in the air, facing a low
// sun, the haze over shaded valleys loses the sun's light alike in the
// froxels and in the brute-force march.
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"

#include "tests/render/correlation.h"
#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 128, kHeight = 64;

struct Frame {
  std::vector<float> hdr, distance;
};

Frame render(const Body& body, const PlaceView& view, bool shadows,
             const std::string& technique = "hillaire") {
  FrameRenderer renderer(kWidth, kHeight);
  FrameOptions options;
  options.terrain_shadows = shadows;
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body), make_technique(technique));
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

// Where alps_sunset's frame 20 and alps_shafts' first frame fly: 1700 m
// over the ground at 46.52 N, 7.95 E, south-west of the Jungfrau (the
// ground 3021 m above the ellipsoid on ETOPO5's Alps).
Geodetic over_the_alps(const Body& earth) {
  Geodetic place{glm::radians(46.52), glm::radians(7.95), 0.0};
  place.height = terrain_ground()(earth, place) + 1700.0;
  return place;
}

TEST(TerrainShadowsGLTest, LowSunShadesTheValleysAndHighSunAlmostNothing) {
  auto context = GlContext::create_headless();
  Body earth = load_body(data_dir() / "planets" / "earth.json");
  // alps_sunset's frame 20: 1700 m over the Alps, looking away from a sun
  // 3 deg up in the west-north-west; then the same sun 60 deg up.
  Geodetic place = over_the_alps(earth);
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

// Per pixel, the share of its radiance that the terrain's shadow in the air
// takes (the technique with terrain_shadows on against off; the ground's
// own shadows in both).
std::vector<double> air_shadow_loss(const Body& body, const PlaceView& view,
                                    const std::string& technique) {
  Frame on = render(body, view, true, technique);
  const char* separator = technique.find(':') == std::string::npos ? ":" : ",";
  Frame off = render(body, view, true, technique + separator + "terrain_shadows=off");
  std::vector<double> loss(size_t(kWidth * kHeight));
  for (size_t p = 0; p < loss.size(); ++p) {
    double a = 0, b = 0;
    for (int c = 0; c < 3; ++c) {
      a += off.hdr[p * 4 + c];
      b += on.hdr[p * 4 + c];
    }
    loss[p] = a > 0 ? 1.0 - b / a : 0.0;
  }
  return loss;
}

// The share of the pixels that lose more than `above` of their radiance.
double share(const std::vector<double>& loss, double above) {
  return double(std::count_if(loss.begin(), loss.end(), [&](double l) { return l > above; })) /
         double(loss.size());
}

TEST(TerrainShadowsGLTest, TheAirInTheShadowOfTheRidgesLosesTheSunsLight) {
  auto context = GlContext::create_headless();
  // The procedural Earth, whose ridges this scene was found over: ETOPO5's
  // Alps, smoothed over 9 km, shade too little air for the comparison at
  // this place (1700 m over their ground, 1.2 % of the pixels lose 5 % by
  // the froxels, 0.1 % by the march; at 800 m and 300 m fewer).
  Body earth = load_body(project_root() / "tests/data/planets/earth_procedural.json");
  // 3000 m over the Alps (about 1700 m over this body's ground), facing a
  // sun 1.5 deg up in the west-north-west, looking a little down over the
  // ridges toward it.
  Geodetic place{glm::radians(46.52), glm::radians(7.95), 3000.0};
  PlaceView view = view_from_place(earth.shape, place, 295.0, -3.0, 60.0, 1.5, 300.0);
  std::vector<double> hillaire = air_shadow_loss(earth, view, "hillaire");
  std::vector<double> raymarch = air_shadow_loss(earth, view, "raymarch");
  // The rows from 30 deg above the view's centre up look well over every
  // ridge's shadow.
  double high_sky = 0;
  for (int y = kHeight * 15 / 16; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      high_sky = std::max(high_sky, std::abs(hillaire[size_t(y * kWidth + x)]));
    }
  }
  const double r = correlation(hillaire, raymarch);
  std::printf(
      "the air's shadow takes 5 %% or more from %.1f %% of the pixels (hillaire), "
      "%.1f %% (raymarch); most taken: %.1f %%, %.1f %%; correlation %.2f; top rows %.2f %%\n",
      100 * share(hillaire, 0.05), 100 * share(raymarch, 0.05),
      100 * *std::max_element(hillaire.begin(), hillaire.end()),
      100 * *std::max_element(raymarch.begin(), raymarch.end()), r, 100 * high_sky);
  EXPECT_GT(share(hillaire, 0.05), 0.05);
  EXPECT_GT(share(raymarch, 0.05), 0.05);
  // Only light taken away (within half-float rounding of the froxels).
  EXPECT_GT(*std::min_element(hillaire.begin(), hillaire.end()), -2e-3);
  EXPECT_GT(*std::min_element(raymarch.begin(), raymarch.end()), -1e-5);
  // The same shadow in the same places by two independent integrations.
  EXPECT_GT(r, 0.7);
  EXPECT_LT(high_sky, 0.01);
}

TEST(TerrainShadowsGLTest, TheAirOfAMarsHollowBelowTheDatumIsShadedToo) {
  auto context = GlContext::create_headless();
  // The procedural Mars, whose hollow this scene was found in.
  Body mars = load_body(project_root() / "tests/data/planets/mars_procedural.json");
  // terrain_mars's frame 1: 3 km over ground 750 m below the datum (the
  // atmosphere's bottom sphere), facing a sun 10 deg up. Every shadow of
  // this relief lies below the datum (the highest at -452 m), so before
  // the air there was marched no pixel changed at all. The dust's optical
  // depth of 0.6 leaves 3 % of the sun's beam at 10 deg: the haze is lit
  // mostly by the sky, and its shadow takes under 1 % of a pixel.
  // raymarch at 256 steps: at its 32 the thin shadowed layer at the far
  // end of a ray falls between its steps.
  Geodetic place{glm::radians(18.65), glm::radians(-134.8), 2250.0};
  PlaceView view = view_from_place(mars.shape, place, 200.0, -10.0, 60.0, 10.0, 200.0);
  std::vector<double> hillaire = air_shadow_loss(mars, view, "hillaire");
  std::vector<double> raymarch = air_shadow_loss(mars, view, "raymarch:view_steps=256");
  const double most_hillaire = *std::max_element(hillaire.begin(), hillaire.end());
  const double most_raymarch = *std::max_element(raymarch.begin(), raymarch.end());
  std::printf(
      "below the datum, the air's shadow takes 0.1 %% or more from %.1f %% of the pixels "
      "(hillaire), %.1f %% (raymarch); most taken: %.2f %%, %.2f %%; correlation %.2f\n",
      100 * share(hillaire, 1e-3), 100 * share(raymarch, 1e-3), 100 * most_hillaire,
      100 * most_raymarch, correlation(hillaire, raymarch));
  EXPECT_GT(share(hillaire, 1e-3), 0.05);
  EXPECT_GT(share(raymarch, 1e-3), 0.02);
  EXPECT_GT(most_hillaire, 3e-3);
  EXPECT_GT(most_raymarch, 3e-3);
  // Only light taken away (within half-float rounding of the froxels).
  EXPECT_GT(*std::min_element(hillaire.begin(), hillaire.end()), -2e-3);
  EXPECT_GT(*std::min_element(raymarch.begin(), raymarch.end()), -1e-5);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
