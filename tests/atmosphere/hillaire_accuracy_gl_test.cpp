// The hillaire technique against the path-traced ground truth of the
// canonical scenes, at 32x16 (the references are cached in data/reference,
// rendered with `planet reference --width 32 --height 16 --spp N`), and
// free of NaN and Inf on every canonical scene.
#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/math/hillaire_math.h"
#include "core/data_paths.h"
#include "core/tone_map.h"
#include "gl/context.h"
#include "lab/accuracy.h"
#include "lab/gpu/scene_render.h"
#include "lab/reference_cache.h"
#include "render/frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 32, kHeight = 16;

struct AccuracyCase {
  const char* scene;
  // Largest relative RMSE (any channel, sun disk excluded) let through:
  // today's measured error plus a fifth, so that a regression fails. The
  // goals (2 % noon and 400 km, 5 % sunset, twilight and Mars) hold but
  // for Mars sunset (the multiply scattered glow of thick dust round a low
  // sun; see docs/accuracy.md#mars-sunset).
  double max_relative_rmse;
};

void PrintTo(const AccuracyCase& c, std::ostream* os) { *os << c.scene; }

// Today's errors + 20 %: a regression guard.
const AccuracyCase kCases[] = {
    {"earth_noon", 0.011},
    {"earth_400km", 0.016},
    {"earth_sunset", 0.025},
    {"earth_twilight", 0.035},
    {"mars_noon", 0.032},
    {"mars_sunset", 0.085},
};

class HillaireAccuracyGLTest : public ::testing::TestWithParam<AccuracyCase> {
 protected:
  void SetUp() override {
    context_ = GlContext::create_headless();
  }
  std::unique_ptr<GlContext> context_;
};

TEST_P(HillaireAccuracyGLTest, MatchesTheGroundTruth) {
  const AccuracyCase& c = GetParam();
  Scene scene = find_scene(c.scene, kWidth, kHeight);
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  auto shipped = shipped_reference_dir() /
                 reference_cache_file(scene, model, shipped_reference_paths(c.scene), ReferenceMode::kRgb).filename();
  ASSERT_TRUE(std::filesystem::exists(shipped) &&
              std::filesystem::exists(reference_noise_file(shipped)))
      << shipped << " or its noise is not shipped; render it with `planet reference --scene "
      << c.scene << " --spp " << shipped_reference_paths(c.scene).label() << " --width " << kWidth << " --height " << kHeight
      << " --out FILE` under PLANET_CACHE_DIR=data and commit it";
  ImageRGB reference = reference_image(scene, shipped_reference_paths(c.scene));
  ImageRGB technique = render_scene_with(scene, "hillaire");
  TechniqueAccuracy accuracy = measure_accuracy(scene, technique, reference);
  std::printf("%s: relative RMSE %.2f%% %.2f%% %.2f%% (open sky %.2f%% %.2f%% %.2f%%)\n", c.scene,
              100 * accuracy.channels[0].relative(), 100 * accuracy.channels[1].relative(),
              100 * accuracy.channels[2].relative(), 100 * accuracy.sky_channels[0].relative(),
              100 * accuracy.sky_channels[1].relative(), 100 * accuracy.sky_channels[2].relative());
  for (float v : technique.pixels) ASSERT_TRUE(std::isfinite(v));
  if (accuracy.worst_relative() > c.max_relative_rmse) {
    std::filesystem::path dir = std::filesystem::absolute("hillaire_accuracy_failures");
    std::filesystem::create_directories(dir);
    write_tone_mapped_png(dir / (scene.name + "_technique.png"), technique, scene.exposure);
    write_tone_mapped_png(dir / (scene.name + "_reference.png"), reference, scene.exposure);
    write_exr(dir / (scene.name + "_technique.exr"), technique);
    write_exr(dir / (scene.name + "_reference.exr"), reference);
    ADD_FAILURE() << c.scene << ": worst relative RMSE " << accuracy.worst_relative() << " above "
                  << c.max_relative_rmse << "; images in " << dir;
  }
}

// The orders of scattering (with the forward gain) against the paper's
// 1 / (1 - f_ms), where the difference is well above the references'
// noise. Measured (worst channel): noon 0.90 vs 7.32 %, twilight 2.93 vs
// 33.5 %, Mars noon 2.63 vs 33.1 %.
TEST_F(HillaireAccuracyGLTest, ScatteringOrdersBeatThePapersSeries) {
  for (const char* name : {"earth_noon", "earth_twilight", "mars_noon"}) {
    Scene scene = find_scene(name, kWidth, kHeight);
    ImageRGB reference = reference_image(scene, shipped_reference_paths(name));
    double orders =
        measure_accuracy(scene, render_scene_with(scene, "hillaire"), reference).worst_relative();
    double paper = measure_accuracy(scene, render_scene_with(scene, "hillaire2020"), reference)
                       .worst_relative();
    std::printf("%s: worst relative RMSE %.2f%% with the orders, %.2f%% with the paper's\n", name,
                100 * orders, 100 * paper);
    EXPECT_LT(orders, 0.8 * paper) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(CanonicalScenes, HillaireAccuracyGLTest, ::testing::ValuesIn(kCases),
                         [](const auto& test_info) { return std::string(test_info.param.scene); });

// Every canonical scene with an atmosphere, dense and strongly forward
// scattering variants included: no NaN or Inf in the image or any LUT.
TEST(HillaireCanonicalGLTest, NoNanOrInfInAnyCanonicalScene) {
  auto context = GlContext::create_headless();
  for (Scene scene : canonical_scenes()) {
    scene.width = kWidth;
    scene.height = kHeight;
    Body body = scene_body(scene);
    if (!body.has_atmosphere()) continue;
    SCOPED_TRACE(scene.name);
    AtmosphereModel model = scene_atmosphere(scene, body);
    FrameRenderer renderer(kWidth, kHeight);
    auto owned = std::make_unique<HillaireTechnique>();
    HillaireTechnique* technique = owned.get();
    renderer.set_body(body, model, std::move(owned));
    renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);
    auto finite = [](const std::vector<float>& v) {
      return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
    };
    EXPECT_TRUE(finite(renderer.read_hdr())) << "image";
    EXPECT_TRUE(
        finite(read_texture_rgba32f(technique->transmittance_lut(), shared::kTransmittanceLutWidth,
                                    shared::kTransmittanceLutHeight)));
    EXPECT_TRUE(
        finite(read_texture_rgba32f(technique->multiple_scattering_lut(),
                                    hillaire::kFieldParts * shared::kMultipleScatteringLutWidth,
                                    shared::kMultipleScatteringLutHeight)));
    if (technique->lut_weight() > 0.0) {
      EXPECT_TRUE(finite(read_texture_rgba32f(technique->sky_view_lut(), shared::kSkyViewLutWidth,
                                              shared::kSkyViewLutHeight)));
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
