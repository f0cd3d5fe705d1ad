// A frame computes only what changed: the tables that depend on the model
// alone are reused while it stays, the sky-view LUT while the altitude and
// the sun round to the same steps, the froxels while the view stays, and
// none of it may leave an image stale or off by more than is stated.
#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "lab/scene.h"
#include "render/frame.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"

#include "tests/atmosphere/image_difference.h"
#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::set<std::string> ran(const FrameStats& stats) {
  std::set<std::string> out;
  for (const PassTiming& p : stats.passes) {
    if (p.ran()) out.insert(p.pass);
  }
  return out;
}

std::set<std::string> reused(const FrameStats& stats) {
  std::set<std::string> out;
  for (const PassTiming& p : stats.passes) {
    if (p.reused) out.insert(p.pass);
  }
  return out;
}

// What a pruned frame may differ by from the frame with nothing pruned: a
// few of a float's last bits. The per-pixel path's own shader (compiled
// without the LUT path and the terrain's shadow, which never reaches that
// high) sums its march in another order of operations: 3.1e-7 at most
// over the scenes and the climb below.
constexpr double kSamePixels = 1e-6;

// The largest of the errors a test measured, and where.
struct WorstError {
  double value = 0.0;
  std::string where;
  void add(double e, const std::string& at) {
    if (e > value) {
      value = e;
      where = at;
    }
  }
};

// The direction of the centre of `pixel` (from the frame's bottom left)
// of a width x height frame of `camera`: where a test puts the sun.
glm::dvec3 toward_pixel(const Camera& camera, glm::dvec2 pixel, int width, int height) {
  const double t = std::tan(0.5 * camera.vertical_fov);
  const glm::dvec2 ndc = 2.0 * pixel / glm::dvec2(width, height) - 1.0;
  return glm::normalize(camera.body_from_camera *
                        glm::dvec3(ndc.x * t * width / height, ndc.y * t, -1.0));
}

// The frame of `view` with the sun on `pixel`, pruned and not: the same to
// kSamePixels, and the sun's disk in it (far brighter than any sky).
void expect_the_suns_disk_as_unpruned(const Body& body, const AtmosphereModel& model,
                                      PlaceView view, glm::dvec2 pixel, int width, int height) {
  view.sun_dir_body = toward_pixel(view.camera, pixel, width, height);
  FrameRenderer pruned(width, height), unpruned(width, height);
  FrameOptions options;
  options.terrain_wait_s = 120.0;
  pruned.set_options(options);
  options.view_pruning = false;
  unpruned.set_options(options);
  pruned.set_body(body, model, make_technique("hillaire"));
  unpruned.set_body(body, model, make_technique("hillaire"));
  pruned.render(view.camera, view.sun_dir_body, 10.0);
  unpruned.render(view.camera, view.sun_dir_body, 10.0);
  std::vector<float> hdr = pruned.read_hdr();
  const std::string where =
      "sun on pixel (" + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) + ")";
  EXPECT_LE(largest_relative_difference(hdr, unpruned.read_hdr()), kSamePixels) << where;
  EXPECT_GT(*std::max_element(hdr.begin(), hdr.end()), 1000.0f) << where;
}

class PassReuseGLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("PLANET_GL_DEBUG", "1", 1);
    context_ = GlContext::create_headless();
    // The procedural Earth, over which the reuse's bound was measured (over
    // ETOPO5 and its detail the climb's worst frame is 1.11e-3).
    body_ = load_body(project_root() / "tests/data/planets/earth_procedural.json");
    model_ = load_atmosphere(body_);
    // The climbs below start this far above the ellipsoid: on the ground
    // over Grindelwald, not inside it.
    TerrainSurface surface(body_.shape, parse_terrain(body_));
    ground_ = ground_height(surface, Geodesy(body_.shape), kAlps);
  }
  // Where the climbs rise, over the Bernese Alps.
  const Geodetic kAlps{glm::radians(46.55), glm::radians(7.98), 0.0};
  std::unique_ptr<GlContext> context_;
  Body body_;
  AtmosphereModel model_;
  double ground_ = 0.0;  // the ground's height at kAlps above the ellipsoid, m
};

// A second frame of the same view over the Alps: the model's three tables,
// the sky view and the froxels are all reused, and the image is the same
// to the byte.
TEST_F(PassReuseGLTest, ASecondFrameOfTheSameViewReusesEveryTableAndDrawsTheSameBytes) {
  FrameRenderer renderer(96, 64);
  renderer.set_body(body_, model_, make_technique("hillaire"));
  auto view = view_from_place(body_.shape, {glm::radians(46.55), glm::radians(7.98), 3000.0},
                              60.0, -5.0, 60.0, 20.0, 200.0);
  FrameStats first = renderer.render(view.camera, view.sun_dir_body, 10.0);
  std::vector<float> first_hdr = renderer.read_hdr();
  FrameStats second = renderer.render(view.camera, view.sun_dir_body, 10.0);
  const std::set<std::string> tables = {"transmittance_lut", "multiple_scattering_lut",
                                        "forward_gain_lut", "sky_view_lut", "aerial_perspective"};
  for (const std::string& table : tables) {
    EXPECT_TRUE(ran(first).count(table)) << table << " did not run in the first frame";
    EXPECT_TRUE(reused(second).count(table)) << table << " was not reused in the second";
  }
  EXPECT_TRUE(ran(second).count("sky")) << "the sky pass draws every frame";
  EXPECT_EQ(renderer.read_hdr(), first_hdr);

  // The camera turns: the froxels follow the view, the rest stays.
  auto turned = view_from_place(body_.shape, {glm::radians(46.55), glm::radians(7.98), 3000.0},
                                70.0, -5.0, 60.0, 20.0, 200.0);
  FrameStats third = renderer.render(turned.camera, turned.sun_dir_body, 10.0);
  EXPECT_TRUE(ran(third).count("aerial_perspective"));
  EXPECT_TRUE(reused(third).count("multiple_scattering_lut"));
  EXPECT_TRUE(reused(third).count("sky_view_lut")) << "same altitude, same sun elevation";
}

// A model changed between two frames (a slider) shows in the very next
// frame: for every technique the image is the one a technique made fresh
// for the new model draws, to the byte.
TEST_F(PassReuseGLTest, AModelChangedBetweenTwoFramesShowsInTheNextFrameAsAFreshTechniqueDrawsIt) {
  AtmosphereModel denser = with_scattering_scaled(model_, 3.0);
  denser.mie_g = 0.6;
  auto view = view_from_place(body_.shape, {glm::radians(46.55), glm::radians(7.98), 3000.0},
                              60.0, -5.0, 60.0, 8.0, 200.0);
  for (const std::string& name : technique_names()) {
    // bruneton's tables for a new model are its precompute: the cheap
    // point keeps this test short.
    const std::string technique = name == "bruneton" ? "bruneton:cheap" : name;
    SCOPED_TRACE(technique);
    FrameRenderer changed(64, 48), fresh(64, 48);
    changed.set_body(body_, model_, make_technique(technique));
    changed.render(view.camera, view.sun_dir_body, 10.0);
    std::vector<float> before = changed.read_hdr();
    changed.set_atmosphere(denser);
    changed.render(view.camera, view.sun_dir_body, 10.0);
    fresh.set_body(body_, denser, make_technique(technique));
    fresh.render(view.camera, view.sun_dir_body, 10.0);
    EXPECT_NE(changed.read_hdr(), before) << "the denser air changed nothing";
    EXPECT_EQ(changed.read_hdr(), fresh.read_hdr());
  }
}

// The sky-view LUT is computed at the altitude and the sun's zenith angle
// rounded to their steps (1/512 of an octave of altitude, 0.0005 degree),
// and reused while they round the same. Against a technique that computes
// every pass every frame at the exact values, no canonical scene, and no
// frame of a climb at sunset that crosses many steps, may differ by more
// than 0.1 % relative RMSE in any channel. Measured: 5.8e-4 at most (the
// climb's frame 16, 260 m over the ground, the Alps in view; 3.8e-4 on
// earth_sunset). Steps of 1/64 octave and 0.01 degree gave 1.6e-3 (a climb
// at 3 km) and 1.9e-3 (earth_twilight, whose sky follows the sun's
// depression closely).
TEST_F(PassReuseGLTest, SkyViewReuseWithinItsStepsChangesNoImageByMoreThanATenthOfAPercent) {
  HillaireTechnique::Settings exact;
  exact.reuse_passes = false;
  WorstError worst;
  auto check = [&](const std::vector<float>& reusing, const std::vector<float>& fresh,
                   const std::string& where) {
    double e = relative_rmse(reusing, fresh);
    EXPECT_LT(e, 1e-3) << where;
    worst.add(e, where);
  };
  for (const Scene& scene : canonical_scenes()) {
    Body body = scene_body(scene);
    if (!body.has_atmosphere()) continue;
    AtmosphereModel model = scene_atmosphere(scene, body);
    FrameRenderer reusing(scene.width, scene.height), fresh(scene.width, scene.height);
    reusing.set_body(body, model, std::make_unique<HillaireTechnique>());
    fresh.set_body(body, model, std::make_unique<HillaireTechnique>(exact));
    reusing.render(scene.camera, scene.sun_dir_body, scene.exposure);
    fresh.render(scene.camera, scene.sun_dir_body, scene.exposure);
    check(reusing.read_hdr(), fresh.read_hdr(), scene.name);
  }
  // A climb from 2 m to 3 km over the ground with the sun setting from 3 to 2 degrees: 25
  // frames, each a few steps of both inputs from the last, one renderer
  // reusing throughout against one computing everything.
  FrameRenderer reusing(96, 48), fresh(96, 48);
  reusing.set_body(body_, model_, std::make_unique<HillaireTechnique>());
  fresh.set_body(body_, model_, std::make_unique<HillaireTechnique>(exact));
  int sky_view_reused = 0;
  for (int i = 0; i < 25; ++i) {
    double f = i / 24.0;
    auto view = view_from_place(body_.shape,
                                {kAlps.lat, kAlps.lon, ground_ + 2.0 * std::pow(1500.0, f)},
                                250.0, 2.0, 70.0, 3.0 - f, 250.0);
    FrameStats stats = reusing.render(view.camera, view.sun_dir_body, 10.0);
    sky_view_reused += int(reused(stats).count("sky_view_lut"));
    fresh.render(view.camera, view.sun_dir_body, 10.0);
    check(reusing.read_hdr(), fresh.read_hdr(), "climb frame " + std::to_string(i));
  }
  EXPECT_EQ(sky_view_reused, 0) << "every frame of the climb moved past a step";
  std::printf("worst relative RMSE of sky-view reuse: %.2e (%s)\n", worst.value,
              worst.where.c_str());
}

// Looking up from the ground no surface is drawn: the froxel volume, which
// serves surfaces alone, is not computed, and the image is the one computed
// with it.
TEST_F(PassReuseGLTest, NoAerialPerspectiveWithoutASurfaceInItsRangeAndTheSameImage) {
  auto up = view_from_place(body_.shape, {glm::radians(46.55), glm::radians(7.98), 4000.0}, 0.0,
                            60.0, 50.0, 10.0, 0.0);
  FrameRenderer pruned(64, 48), unpruned(64, 48);
  FrameOptions options;
  options.view_pruning = false;
  unpruned.set_options(options);
  pruned.set_body(body_, model_, make_technique("hillaire"));
  unpruned.set_body(body_, model_, make_technique("hillaire"));
  FrameStats stats = pruned.render(up.camera, up.sun_dir_body, 10.0);
  // Tiles are drawn (the bound of the one under the camera holds it), but
  // none covers a pixel.
  for (float d : pruned.read_distance(up.camera)) ASSERT_TRUE(std::isinf(d)) << "a surface in view";
  EXPECT_FALSE(ran(stats).count("aerial_perspective"));
  EXPECT_FALSE(reused(stats).count("aerial_perspective"));
  EXPECT_TRUE(ran(unpruned.render(up.camera, up.sun_dir_body, 10.0)).count("aerial_perspective"));
  EXPECT_EQ(pruned.read_hdr(), unpruned.read_hdr());
}

// From 40 000 km the sky pass marches only the pixels inside the shell's
// screen bound; the others are space, and the sun's disk there, drawn to
// the same values (kSamePixels).
TEST_F(PassReuseGLTest, FromSpaceOnlyThePixelsInTheShellsBoundAreShadedAndTheImageIsTheSame) {
  auto view = view_from_place(body_.shape, {glm::radians(10.0), glm::radians(20.0), 40000e3},
                              30.0, -75.0, 50.0, 30.0, 0.0);
  // The sun in the frame, in space beside the disk, on the centre of pixel
  // (80, 50): the disk is smaller than a pixel.
  const int width = 96, height = 64;
  view.sun_dir_body = toward_pixel(view.camera, {80.5, 50.5}, width, height);
  FrameRenderer pruned(width, height), unpruned(width, height);
  FrameOptions options;
  options.view_pruning = false;
  unpruned.set_options(options);
  auto technique = std::make_unique<HillaireTechnique>();
  HillaireTechnique* hillaire = technique.get();
  pruned.set_body(body_, model_, std::move(technique));
  unpruned.set_body(body_, model_, make_technique("hillaire"));
  FrameStats stats = pruned.render(view.camera, view.sun_dir_body, 10.0);
  unpruned.render(view.camera, view.sun_dir_body, 10.0);
  EXPECT_TRUE(ran(stats).count("space"));
  EXPECT_LT(hillaire->shaded_fraction(), 0.5);
  EXPECT_GT(hillaire->shaded_fraction(), 0.05);
  std::vector<float> hdr = pruned.read_hdr();
  EXPECT_LE(largest_relative_difference(hdr, unpruned.read_hdr()), kSamePixels);
  EXPECT_GT(*std::max_element(hdr.begin(), hdr.end()), 1000.0f) << "the sun's disk is in view";
}

// On the ground the sky pass draws every pixel without the sun's disk,
// then the whole shader over the disk's screen bound (hillaire_sky.frag):
// the same image as the whole shader over every pixel, with the sun's disk
// in it, where the disk lies inside the frame and where it lies on its
// left edge (a bound clamped to the frame).
TEST_F(PassReuseGLTest, OnTheGroundTheSunsDiskIsDrawnWithinItsBoundAndTheImageIsTheSame) {
  // 5 km up over the Alps, looking up: no peak hides the sun, and the
  // froxels and the march still serve the peaks at the frame's foot.
  auto view = view_from_place(body_.shape, {glm::radians(46.55), glm::radians(7.98), 5000.0},
                              60.0, 20.0, 50.0, 25.0, 0.0);
  for (glm::dvec2 pixel : {glm::dvec2(30.5, 40.5), glm::dvec2(0.2, 45.5)}) {
    expect_the_suns_disk_as_unpruned(body_, model_, view, pixel, 96, 64);
  }
}

// Over (the procedural) Mars's lowlands, 748 m below the bottom sphere, the camera
// is lifted onto it and rays under its horizon are raised
// (lifted_horizon.glsl): there the first part of the sky pass keeps the
// sun's disk. The sun 15 deg up ahead (lower, Mars's dust dims its disk
// to nothing): the same image as the unpruned frame's, the disk in it.
TEST_F(PassReuseGLTest, OverGroundBelowTheBottomSphereTheSunsDiskIsTheUnprunedFramesToo) {
  // The procedural Mars, whose lowland lies there.
  Body mars = load_body(project_root() / "tests/data/planets/mars_procedural.json");
  auto view = view_from_place(mars.shape, {glm::radians(18.65), glm::radians(-134.8), -747.912},
                              90.0, 10.0, 20.0, 10.0, 0.0);
  expect_the_suns_disk_as_unpruned(mars, load_atmosphere(mars), view, {48.5, 40.5}, 96, 54);
}

// Every pruning by view (no froxels without a surface in their range, no
// march outside the shell's screen bound, the per-pixel path's own shader)
// leaves the image as it was, to a few of a float's last bits
// (kSamePixels): on every canonical scene, and on a climb from 2 m over the ground to
// 1e8 m.
TEST_F(PassReuseGLTest, PruningByViewChangesNoPixelOnTheCanonicalScenesOrAClimbTo1e8m) {
  auto compare = [](const Body& body, const AtmosphereModel& model, int width, int height,
                    const Camera& camera, const glm::dvec3& sun, const std::string& where) {
    FrameRenderer pruned(width, height), unpruned(width, height);
    FrameOptions options;
    options.view_pruning = false;
    unpruned.set_options(options);
    pruned.set_body(body, model, make_technique("hillaire"));
    unpruned.set_body(body, model, make_technique("hillaire"));
    FrameStats stats = pruned.render(camera, sun, 10.0);
    unpruned.render(camera, sun, 10.0);
    EXPECT_LE(largest_relative_difference(pruned.read_hdr(), unpruned.read_hdr()),
              kSamePixels)
        << where;
    return stats;
  };
  for (const Scene& scene : canonical_scenes()) {
    Body body = scene_body(scene);
    if (!body.has_atmosphere()) continue;
    compare(body, scene_atmosphere(scene, body), scene.width, scene.height, scene.camera,
            scene.sun_dir_body, scene.name);
  }
  int pruned_frames = 0;
  for (double height : {2.0, 100.0, 3e3, 30e3, 90e3, 400e3, 3e6, 4e7, 1e8}) {
    auto view = view_from_place(body_.shape, {kAlps.lat, kAlps.lon, ground_ + height}, 60.0,
                                height < 1e5 ? 5.0 : -60.0, 60.0, 25.0, 100.0);
    FrameStats stats = compare(body_, model_, 96, 54, view.camera, view.sun_dir_body,
                               "climb at " + std::to_string(height) + " m");
    pruned_frames += int(ran(stats).count("space"));
  }
  EXPECT_GE(pruned_frames, 2) << "the bound left pixels out from 4e7 and 1e8 m at least";
  // Mars's dust scatters each channel its own way: from 400 km, on the
  // per-pixel path alone, the shader without the LUT path for coloured Mie
  // (Earth's is grey).
  Body mars = load_body(data_dir() / "planets" / "mars.json");
  auto above_mars = view_from_place(mars.shape, {glm::radians(-4.5), glm::radians(137.4), 400e3},
                                    60.0, -60.0, 60.0, 25.0, 100.0);
  FrameStats stats = compare(mars, load_atmosphere(mars), 96, 54, above_mars.camera,
                             above_mars.sun_dir_body, "Mars from 400 km");
  EXPECT_FALSE(ran(stats).count("sky_view_lut")) << "the per-pixel path alone";
}

// From outside the shell the sky pass reads the space-view LUT where it
// marched every pixel (space_view_lut.glsl): the image stays within
// kSpaceViewRmse (relative RMSE over the lit pixels, the worst channel; the
// worst, 0.84 %, is the twilight limb from 3000 km) of the march's on
// every
// canonical scene from outside the shell and on views of Earth (with its
// terrain) and Mars from 400 km to 1e8 m, the limb and the sun's glow on
// it in view; the table is marched once for a view and reused after.
constexpr double kSpaceViewRmse = 0.01;
TEST_F(PassReuseGLTest, FromSpaceTheSpaceViewLutDrawsWhatTheMarchDrawsToWithinAPercent) {
  HillaireTechnique::Settings march, with_lut;
  march.space_view_lut = false;
  with_lut.space_view_min_pixels = 0.0;  // these frames are small
  WorstError worst;
  int drawn = 0;
  auto compare = [&](const Body& body, const AtmosphereModel& model, int width, int height,
                     const Camera& camera, const glm::dvec3& sun, const std::string& where) {
    FrameRenderer lut(width, height), marched(width, height);
    auto technique = std::make_unique<HillaireTechnique>(with_lut);
    HillaireTechnique* hillaire = technique.get();
    lut.set_body(body, model, std::move(technique));
    marched.set_body(body, model, std::make_unique<HillaireTechnique>(march));
    FrameStats first = lut.render(camera, sun, 10.0);
    marched.render(camera, sun, 10.0);
    if (!hillaire->used_space_view()) return;
    ++drawn;
    EXPECT_TRUE(ran(first).count("space_view_lut")) << where;
    EXPECT_TRUE(reused(lut.render(camera, sun, 10.0)).count("space_view_lut")) << where;
    double e = relative_rmse(lut.read_hdr(), marched.read_hdr(), true);
    EXPECT_LT(e, kSpaceViewRmse) << where;
    worst.add(e, where);
  };
  for (const Scene& scene : canonical_scenes()) {
    Body body = scene_body(scene);
    if (!body.has_atmosphere()) continue;
    compare(body, scene_atmosphere(scene, body), scene.width, scene.height, scene.camera,
            scene.sun_dir_body, scene.name);
  }
  for (double height : {400e3, 3e6, 4e7, 1e8}) {
    for (double sun_elevation : {25.0, 2.0, -4.0}) {
      auto view = view_from_place(body_.shape, {kAlps.lat, kAlps.lon, ground_ + height}, 60.0,
                                  height < 1e6 ? -18.0 : -89.0, 60.0, sun_elevation, 40.0);
      compare(body_, model_, 128, 72, view.camera, view.sun_dir_body,
              "Earth from " + std::to_string(height) + " m, sun at " +
                  std::to_string(sun_elevation) + " deg");
    }
  }
  // The sun's disk in the frame, in space above the limb and lower down.
  for (glm::dvec2 pixel : {glm::dvec2(64.5, 66.5), glm::dvec2(30.5, 40.5)}) {
    auto view = view_from_place(body_.shape, {kAlps.lat, kAlps.lon, ground_ + 400e3}, 60.0,
                                -18.0, 60.0, 25.0, 40.0);
    view.sun_dir_body = toward_pixel(view.camera, pixel, 128, 72);
    FrameRenderer lut(128, 72);
    lut.set_body(body_, model_, std::make_unique<HillaireTechnique>(with_lut));
    lut.render(view.camera, view.sun_dir_body, 10.0);
    std::vector<float> hdr = lut.read_hdr();
    EXPECT_GT(*std::max_element(hdr.begin(), hdr.end()), 1000.0f) << "the sun's disk is drawn";
    compare(body_, model_, 128, 72, view.camera, view.sun_dir_body,
            "the sun on pixel (" + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) + ")");
  }
  Body mars = load_body(data_dir() / "planets" / "mars.json");
  auto above_mars = view_from_place(mars.shape, {glm::radians(-4.5), glm::radians(137.4), 400e3},
                                    60.0, -18.0, 60.0, 10.0, 20.0);
  compare(mars, load_atmosphere(mars), 128, 72, above_mars.camera, above_mars.sun_dir_body,
          "Mars from 400 km");
  EXPECT_GE(drawn, 16) << "the views outside the shell drew with the LUT";
  // With the default settings a frame this small is marched: the table
  // would cost more than the march of its 9216 pixels.
  auto technique = std::make_unique<HillaireTechnique>();
  HillaireTechnique* hillaire = technique.get();
  FrameRenderer small(128, 72);
  small.set_body(mars, load_atmosphere(mars), std::move(technique));
  small.render(above_mars.camera, above_mars.sun_dir_body, 10.0);
  EXPECT_FALSE(hillaire->used_space_view());
  std::printf("worst relative RMSE of the space-view LUT: %.2e (%s)\n", worst.value,
              worst.where.c_str());
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
