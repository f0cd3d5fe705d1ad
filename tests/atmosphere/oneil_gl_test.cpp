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
#include "lab/reference_cache.h"
#include "lab/scene_render.h"
#include "render/frame.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace planet {
namespace {

constexpr int kWidth = 32, kHeight = 16;

Scene small_scene(const std::string& name) {
  Scene scene = find_scene(name);
  scene.width = kWidth;
  scene.height = kHeight;
  return scene;
}

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
  Scene scene = small_scene(c.scene);
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

// The requirement: on Mars and the asteroid, whose ratios of scale
// height to thickness are not the chapter's, the fitted scale function
// beats the fixed one in every channel. Measured against what the
// scale function approximates, single scattering, by the raymarch
// baseline at its fine quality, with the absorber (which O'Neil's model
// lacks) out of both; the path-traced references hold multiple scattering,
// which no scale function brings. Measured (relative RMSE, worst channel):
// fitted 0.39 / 1.39 / 0.25 / 0.94 %, chapter 6.6 / 103 / 40 / 154 % on Mars
// noon, Mars sunset, the asteroid's surface and the asteroid from space.
// Against the path-traced references instead, the chapter's polynomial is
// the nearer on Mars (its error offsets the missing multiple scattering):
// planet accuracy --technique oneil:scale=chapter shows it.
TEST(OneilScaleGLTest, FittedScaleBeatsTheChaptersOnMarsAndTheAsteroid) {
  auto context = GlContext::create_headless();
  for (const char* name : {"mars_noon", "mars_sunset", "asteroid_surface", "asteroid_space"}) {
    Scene scene = small_scene(name);
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

// exposure=chapter: the technique writes the chapter's display values
// 1 - exp(-exposure L) of the radiance it draws by default, and the frame's
// tone map passes them through (to 8 bits, with its half-step dither).
TEST(OneilExposureGLTest, ChapterExposureReplacesTheToneMap) {
  auto context = GlContext::create_headless();
  Scene scene = small_scene("earth_noon");
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  auto draw = [&](const std::string& technique, std::vector<uint8_t>* ldr) {
    FrameRenderer renderer(kWidth, kHeight);
    renderer.set_body(body, model, make_technique(technique));
    renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
    if (ldr) *ldr = renderer.read_ldr();
    return renderer.read_hdr();
  };
  std::vector<float> radiance = draw("oneil", nullptr);
  std::vector<uint8_t> ldr;
  std::vector<float> display = draw("oneil:exposure=chapter", &ldr);
  ASSERT_EQ(radiance.size(), display.size());
  int differ = 0;
  for (size_t i = 0; i < radiance.size(); ++i) {
    if (i % 4 == 3) continue;
    float expected = 1.0f - std::exp(-float(scene.exposure) * radiance[i]);
    EXPECT_NEAR(display[i], expected, 1e-5f) << "texel " << i;
    EXPECT_NEAR(float(ldr[i]), 255.0f * display[i], 1.0f) << "texel " << i;
    differ += std::abs(display[i] - radiance[i]) > 1e-3f;
  }
  EXPECT_GT(differ, 0);
}

// The sun's disk seen past the planet from deep space, where no ray meets
// the atmosphere, as the raymarch baseline draws it (the same shared
// sun.glsl): a 0.2 deg view into the disk's middle.
TEST(OneilSunGLTest, SunDiskShowsFromDeepSpace) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / "earth.json");
  body.terrain = nullptr;
  AtmosphereModel model = load_atmosphere(body);
  auto view = view_from_place(body.shape, {glm::radians(46.5), glm::radians(8.0), 1e9}, 90.0, 30.0,
                              0.2, 30.0, 90.0);
  auto centre = [&](const std::string& technique) {
    FrameRenderer renderer(kWidth, kHeight);
    renderer.set_body(body, model, make_technique(technique));
    renderer.render(view.camera, view.sun_dir_body, 10.0);
    std::vector<float> hdr = renderer.read_hdr();
    return hdr[(size_t(kHeight / 2) * kWidth + kWidth / 2) * 4 + 1];
  };
  float raymarch = centre("raymarch"), oneil = centre("oneil");
  EXPECT_GT(raymarch, 1e3f);
  EXPECT_NEAR(oneil / raymarch, 1.0f, 1e-4f);
}

// Every canonical scene, and the camera at 1 m, 100 km, 1e6 km and inside
// the planet on every body with the sun high, low, set and at the nadir:
// no NaN or Inf anywhere in the image.
TEST(OneilCanonicalGLTest, NoNanOrInfInAnySceneOrView) {
  auto context = GlContext::create_headless();
  for (Scene scene : canonical_scenes()) {
    Body body = scene_body(scene);
    if (!body.has_atmosphere()) continue;
    SCOPED_TRACE(scene.name);
    scene.width = kWidth;
    scene.height = kHeight;
    EXPECT_TRUE(all_finite(render_scene_with(scene, "oneil").pixels));
  }
  for (const char* planet : {"earth", "mars", "asteroid"}) {
    Body body = load_body(data_dir() / "planets" / (std::string(planet) + ".json"));
    body.terrain = nullptr;  // the camera stays where it is put
    AtmosphereModel model = load_atmosphere(body);
    FrameRenderer renderer(kWidth, kHeight);
    renderer.set_body(body, model, make_technique("oneil"));
    struct View {
      const char* what;
      double height, pitch_deg;
    };
    for (const View& view : {View{"1 m", 1.0, 5.0}, View{"100 km", 100e3, -20.0},
                             View{"1e6 km", 1e9, -90.0}, View{"inside", -2000.0, 5.0}}) {
      for (double sun_elevation : {60.0, 2.0, -5.0, -90.0}) {
        SCOPED_TRACE(::testing::Message()
                     << planet << ", " << view.what << ", sun at " << sun_elevation << " deg");
        auto v = view_from_place(body.shape, {glm::radians(46.5), glm::radians(8.0), view.height},
                                 0.0, view.pitch_deg, 90.0, sun_elevation, 90.0);
        renderer.render(v.camera, v.sun_dir_body, 10.0);
        EXPECT_TRUE(all_finite(renderer.read_hdr()));
      }
    }
  }
}

}  // namespace
}  // namespace planet
