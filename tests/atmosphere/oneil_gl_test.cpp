// The oneil technique through the frame: against the path-traced ground
// truth of the canonical scenes at 32x16 (the shipped references), free of
// NaN and Inf from the ground to deep space and inside the planet on every
// body, and with its fitted scale function closer than the chapter's
// polynomial to single scattering on Mars and the asteroid.
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "core/tone_map.h"
#include "gl/context.h"
#include "lab/accuracy.h"
#include "lab/gpu/scene_render.h"
#include "lab/reference_cache.h"
#include "render/frame.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 32, kHeight = 16;

bool all_finite(const std::vector<float>& values) {
  return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

struct AccuracyCase {
  const char* scene;
  PathBudget spp;  // of the shipped reference
  // Largest relative RMSE (any channel, sun disk excluded) let through:
  // today's measured error plus a fifth, a regression guard. O'Neil's
  // technique has single scattering only and no absorber, so it is far
  // from the ground truth where multiple scattering or ozone count.
  double max_relative_rmse;
};

void PrintTo(const AccuracyCase& c, std::ostream* os) { *os << c.scene; }

// Today's worst channel (earth_noon 51.5 %, sunset 49.1 %, twilight 75.0 %,
// 400 km 61.5 %, Mars noon 61.6 %, Mars sunset 121 %) + 20 %.
const AccuracyCase kCases[] = {
    {"earth_noon", PathBudget({40960, 147456, 335872}), 0.62},
    {"earth_400km", PathBudget({98304, 180224, 655360}), 0.74},
    {"earth_sunset", PathBudget({24576, 126976, 811008}), 0.59},
    {"earth_twilight", PathBudget({430080, 339968, 704512}), 0.90},
    {"mars_noon", 196608, 0.74},
    {"mars_sunset", PathBudget({184320, 143360, 131072}), 1.45},
};

class OneilAccuracyGLTest : public ::testing::TestWithParam<AccuracyCase> {
 protected:
  void SetUp() override { context_ = GlContext::create_headless(); }
  std::unique_ptr<GlContext> context_;
};

TEST_P(OneilAccuracyGLTest, StaysWithinTodaysErrorOfTheGroundTruth) {
  const AccuracyCase& c = GetParam();
  Scene scene = find_scene(c.scene, kWidth, kHeight);
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  auto shipped = shipped_reference_dir() /
                 reference_cache_file(scene, model, c.spp, ReferenceMode::kRgb).filename();
  ASSERT_TRUE(std::filesystem::exists(shipped)) << shipped << " is not shipped";
  ImageRGB reference = reference_image(scene, c.spp);
  ImageRGB technique = render_scene_with(scene, "oneil");
  TechniqueAccuracy accuracy = measure_accuracy(scene, technique, reference);
  std::printf("%s: relative RMSE %.2f%% %.2f%% %.2f%%\n", c.scene,
              100 * accuracy.channels[0].relative(), 100 * accuracy.channels[1].relative(),
              100 * accuracy.channels[2].relative());
  ASSERT_TRUE(all_finite(technique.pixels));
  if (accuracy.worst_relative() > c.max_relative_rmse) {
    std::filesystem::path dir = std::filesystem::absolute("oneil_accuracy_failures");
    std::filesystem::create_directories(dir);
    write_tone_mapped_png(dir / (scene.name + "_technique.png"), technique, scene.exposure);
    write_tone_mapped_png(dir / (scene.name + "_reference.png"), reference, scene.exposure);
    write_exr(dir / (scene.name + "_technique.exr"), technique);
    write_exr(dir / (scene.name + "_reference.exr"), reference);
    ADD_FAILURE() << c.scene << ": worst relative RMSE " << accuracy.worst_relative() << " above "
                  << c.max_relative_rmse << "; images in " << dir;
  }
}

INSTANTIATE_TEST_SUITE_P(CanonicalScenes, OneilAccuracyGLTest, ::testing::ValuesIn(kCases),
                         [](const auto& test_info) { return std::string(test_info.param.scene); });

// The scene drawn by a technique with the body's absorber taken out.
ImageRGB render_without_absorber(const Scene& scene, const std::string& technique) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  model.absorber.absorption = glm::dvec3(0.0);
  FrameRenderer renderer(scene.width, scene.height);
  renderer.set_body(body, model, make_technique(technique));
  renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
  return image_from_gl(scene.width, scene.height, renderer.read_hdr());
}

// On Mars and the asteroid, whose ratios of scale height to thickness are
// not the chapter's, the fitted scale function beats the fixed one in every
// channel. Measured against what a scale function approximates, single
// scattering, twice:
// - by the raymarch baseline at its fine quality, with the absorber (which
//   O'Neil's model lacks) out of both. Measured (relative RMSE, worst
//   channel): fitted 0.39 / 1.39 / 0.25 / 0.94 %, chapter 6.6 / 103 / 40 /
//   154 % on Mars noon, Mars sunset, the asteroid's surface and from space;
// - by the path tracer's first order alone (the shipped `--max-order 1`
//   references), the absorber in, over the open sky (the ground's light
//   from the sky is the second order). Measured (R / G / B): fitted 2.2 /
//   2.2 / 2.2 %, chapter 8.6 / 7.8 / 7.7 % on Mars noon; the rest are
//   printed.
// Against the full ground truth instead, the chapter's polynomial is the
// nearer on Mars (its error offsets the missing multiple scattering):
// planet accuracy --technique oneil:scale=chapter shows it.
TEST(OneilScaleGLTest, FittedScaleBeatsTheChaptersOnMarsAndTheAsteroid) {
  auto context = GlContext::create_headless();
  for (const char* name : {"mars_noon", "mars_sunset", "asteroid_surface", "asteroid_space"}) {
    Scene scene = find_scene(name, kWidth, kHeight);
    ImageRGB truth = render_without_absorber(scene, "raymarch:view_steps=128,light_steps=64");
    TechniqueAccuracy fitted =
        measure_accuracy(scene, render_without_absorber(scene, "oneil:samples=16"), truth);
    TechniqueAccuracy chapter = measure_accuracy(
        scene, render_without_absorber(scene, "oneil:samples=16,scale=chapter"), truth);
    for (int c = 0; c < 3; ++c) {
      std::printf("%s channel %d: relative RMSE %.2f%% fitted, %.2f%% chapter\n", name, c,
                  100 * fitted.channels[size_t(c)].relative(),
                  100 * chapter.channels[size_t(c)].relative());
      EXPECT_LT(fitted.channels[size_t(c)].relative(), chapter.channels[size_t(c)].relative())
          << name << " channel " << c;
    }
  }
}

constexpr int kFirstOrderPaths = 65536;  // of the shipped --max-order 1 references

TEST(OneilScaleGLTest, FittedScaleBeatsTheChaptersAgainstThePathTracersFirstOrder) {
  auto context = GlContext::create_headless();
  for (const char* name : {"mars_noon", "mars_sunset", "asteroid_surface", "asteroid_space"}) {
    Scene scene = find_scene(name, kWidth, kHeight);
    scene.max_order = 1;
    Body body = scene_body(scene);
    AtmosphereModel model = scene_atmosphere(scene, body);
    PathBudget paths(kFirstOrderPaths);
    auto shipped = shipped_reference_dir() /
                   reference_cache_file(scene, model, paths, ReferenceMode::kRgb).filename();
    ASSERT_TRUE(std::filesystem::exists(shipped)) << shipped << " is not shipped";
    ImageRGB truth = reference_image(scene, paths);
    TechniqueAccuracy fitted = measure_accuracy(scene, render_scene_with(scene, "oneil"), truth);
    TechniqueAccuracy chapter =
        measure_accuracy(scene, render_scene_with(scene, "oneil:scale=chapter"), truth);
    ASSERT_GT(fitted.sky_pixels, 0) << name;
    for (int c = 0; c < 3; ++c) {
      double f = fitted.sky_channels[size_t(c)].relative();
      double h = chapter.sky_channels[size_t(c)].relative();
      std::printf("%s channel %d, open sky, against the first order: %.2f%% fitted, %.2f%% "
                  "chapter\n",
                  name, c, 100 * f, 100 * h);
      EXPECT_LT(f, h) << name << " channel " << c;
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
