// The schedules a technique takes (gl/schedule.h): software, the passes
// split for a rasteriser that runs every side of a branch, and plain, one
// program for every pixel, for a GPU. Either draws the same sky within
// what is stated here, and auto takes software on llvmpipe.
#include "atmosphere/gpu/bruneton/bruneton_technique.h"
#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "gl/context.h"
#include "gl/schedule.h"
#include "render/frame.h"

#include "tests/atmosphere/image_difference.h"
#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <string>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ScheduleTest, SoftwareRasterisersByNameAndAnyOtherRendererPlain) {
  EXPECT_EQ(schedule_for_renderer("llvmpipe (LLVM 15.0.6, 256 bits)"), Schedule::kSoftware);
  EXPECT_EQ(schedule_for_renderer("softpipe"), Schedule::kSoftware);
  EXPECT_EQ(schedule_for_renderer("SwiftShader Device (Subzero) (0x0000C0DE)"),
            Schedule::kSoftware);
  EXPECT_EQ(schedule_for_renderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"), Schedule::kPlain);
  // LLVM in a GPU driver's name makes no software rasteriser.
  EXPECT_EQ(schedule_for_renderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7)"),
            Schedule::kPlain);
}

TEST(ScheduleTest, AutoSoftwareOrPlainAndAnythingElseAnErrorNamingTheOption) {
  EXPECT_EQ(parse_schedule("auto", "--schedule"), std::nullopt);
  EXPECT_EQ(parse_schedule("software", "--schedule"), Schedule::kSoftware);
  EXPECT_EQ(parse_schedule("plain", "--schedule"), Schedule::kPlain);
  try {
    parse_schedule("fast", "--schedule");
    FAIL() << "fast is no schedule";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--schedule"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fast"), std::string::npos) << e.what();
  }
}

class ScheduleGLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("PLANET_GL_DEBUG", "1", 1);
    context_ = GlContext::create_headless();
    earth_ = load_body(data_dir() / "planets" / "earth.json");
    model_ = load_atmosphere(earth_);
  }
  void TearDown() override { set_schedule(std::nullopt); }
  std::unique_ptr<GlContext> context_;
  Body earth_;
  AtmosphereModel model_;
};

TEST_F(ScheduleGLTest, AutoTakesTheRenderersScheduleAndACommandsChoiceWins) {
  set_schedule(std::nullopt);
  const std::string renderer = context_->renderer();
  EXPECT_EQ(current_schedule(), schedule_for_renderer(renderer));
  if (renderer.find("llvmpipe") != std::string::npos) {
    EXPECT_EQ(current_schedule(), Schedule::kSoftware) << renderer;
    EXPECT_EQ(static_cast<HillaireTechnique&>(*make_technique("hillaire")).schedule(),
              Schedule::kSoftware);
  }
  set_schedule(Schedule::kPlain);
  EXPECT_EQ(static_cast<HillaireTechnique&>(*make_technique("hillaire")).schedule(),
            Schedule::kPlain);
}

// How far the plain schedule's frame may be from the software one's, as
// the lab's relative RMSE and the worst pixel. Each pixel runs the same
// code either way: on the ground the whole shader against its parts
// (stencil classes, march tiles, the sun's disk again), from 400 km the
// whole shader against its variant without the LUT path, from space the
// space-view LUT's two kinds of pixel in one program against a program
// each. Variants compiled apart may order a sum differently, a few of a
// float's last bits (3.1e-7 between the per-pixel variant and the whole
// shader in PassReuseGLTest's scenes). Measured here on llvmpipe: the
// same bits on the ground and from the space-view LUT; marched from 400 km
// a relative RMSE of 5.4e-8 and a worst pixel 2.4e-7 off.
constexpr double kSchedulesRmse = 1e-6;
constexpr double kSchedulesWorstPixel = 1e-6;

struct View {
  std::string where;
  PlaceView view;
  bool space_view_lut = true;  // from space, the sky pass reads the space-view LUT
};

// The frame of `view` drawn by the technique that `make` builds for the
// schedule.
std::vector<float> draw(const Body& body, const AtmosphereModel& model, const PlaceView& view,
                        const std::function<std::unique_ptr<AtmosphereTechnique>(Schedule)>& make,
                        Schedule schedule) {
  FrameRenderer renderer(96, 48);
  FrameOptions options;
  options.terrain_wait_s = 120.0;
  renderer.set_options(options);
  renderer.set_body(body, model, make(schedule));
  renderer.render(view.camera, view.sun_dir_body, 10.0);
  std::vector<float> hdr = renderer.read_hdr();
  EXPECT_GT(*std::max_element(hdr.begin(), hdr.end()), 0.0f) << "a black frame";
  return hdr;
}

TEST_F(ScheduleGLTest, BothSchedulesDrawTheSameSky) {
  const Geodetic alps{glm::radians(46.55), glm::radians(7.98), 0.0};
  const View views[] = {
      {"the ground over the Alps, toward the horizon",
       view_from_place(earth_.shape, {alps.lat, alps.lon, 3000.0}, 60.0, -8.0, 60.0, 12.0, 40.0)},
      {"400 km, the limb in view, marched",
       view_from_place(earth_.shape, {alps.lat, alps.lon, 400e3}, 60.0, -18.0, 60.0, 25.0, 40.0),
       false},
      {"400 km, the limb in view, from the space-view LUT",
       view_from_place(earth_.shape, {alps.lat, alps.lon, 400e3}, 60.0, -18.0, 60.0, 25.0, 40.0)},
      {"40 000 km, the whole disk",
       view_from_place(earth_.shape, {alps.lat, alps.lon, 4e7}, 60.0, -89.0, 60.0, 25.0, 40.0)},
  };
  double worst_rmse = 0.0, worst_pixel = 0.0;
  for (const View& v : views) {
    auto hillaire = [&v](Schedule schedule) {
      HillaireTechnique::Settings settings;
      settings.schedule = schedule;
      settings.space_view_lut = v.space_view_lut;
      settings.space_view_min_pixels = 0.0;  // this frame is small
      return std::make_unique<HillaireTechnique>(settings);
    };
    const std::vector<float> software = draw(earth_, model_, v.view, hillaire, Schedule::kSoftware);
    const std::vector<float> plain = draw(earth_, model_, v.view, hillaire, Schedule::kPlain);
    const double rmse = relative_rmse(plain, software, true);
    const double pixel = largest_relative_difference(plain, software);
    EXPECT_LE(rmse, kSchedulesRmse) << v.where;
    EXPECT_LE(pixel, kSchedulesWorstPixel) << v.where;
    worst_rmse = std::max(worst_rmse, rmse);
    worst_pixel = std::max(worst_pixel, pixel);
    std::printf("%-48s relative RMSE %.3g, worst pixel %.3g\n", v.where.c_str(), rmse, pixel);
  }
  std::printf("worst: relative RMSE %.3g, worst pixel %.3g\n", worst_rmse, worst_pixel);
}

// Bruneton's classes (the stencil's, a program each, or one program's
// branches) run the same code on each pixel: the same image to within
// kBrunetonSchedulesWorstPixel (as the Hillaire technique's), measured 0
// on llvmpipe: the same bits. Small tables: the schedules read them alike
// whatever their size.
constexpr double kBrunetonSchedulesWorstPixel = 1e-6;

TEST_F(ScheduleGLTest, BothSchedulesDrawTheSameBrunetonSky) {
  const Geodetic alps{glm::radians(46.55), glm::radians(7.98), 0.0};
  const View views[] = {
      {"the ground over the Alps, toward the horizon",
       view_from_place(earth_.shape, {alps.lat, alps.lon, 3000.0}, 60.0, -8.0, 60.0, 12.0, 40.0)},
      {"40 000 km, the whole disk",
       view_from_place(earth_.shape, {alps.lat, alps.lon, 4e7}, 60.0, -89.0, 60.0, 25.0, 40.0)},
  };
  auto bruneton = [](Schedule schedule) {
    BrunetonTechnique::Settings settings;
    settings.transmittance_width = 64;
    settings.transmittance_height = 16;
    settings.irradiance_width = 16;
    settings.irradiance_height = 4;
    settings.r = 8;
    settings.mu = 32;
    settings.mu_s = 16;
    settings.nu = 4;
    settings.orders = 2;
    settings.schedule = schedule;
    return std::make_unique<BrunetonTechnique>(settings);
  };
  for (const View& v : views) {
    const std::vector<float> software = draw(earth_, model_, v.view, bruneton, Schedule::kSoftware);
    const std::vector<float> plain = draw(earth_, model_, v.view, bruneton, Schedule::kPlain);
    const double pixel = largest_relative_difference(plain, software);
    EXPECT_LE(pixel, kBrunetonSchedulesWorstPixel) << v.where;
    std::printf("bruneton, %-48s worst pixel %.3g\n", v.where.c_str(), pixel);
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
