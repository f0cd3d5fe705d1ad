// Frames rendered headless and checked for what a person must see in them.
#include "atmosphere/gpu/registry.h"
#include "render/frame.h"

#include "core/data_paths.h"
#include "gl/context.h"
#include "sim/geodesy.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

class FrameGLTest : public ::testing::Test {
 protected:
  static constexpr int kSize = 64;

  void SetUp() override {
    context_ = GlContext::create_headless();
    body_ = load_body(data_dir() / "planets" / "earth.json");
    // These test the sky over a smooth Earth: without relief the camera
    // stays above ground wherever a test puts it.
    body_.terrain = nullptr;
    AtmosphereModel model = load_atmosphere(body_);
    renderer_ = std::make_unique<FrameRenderer>(kSize, kSize);
    renderer_->set_body(body_, model, make_technique("raymarch"));
  }

  // Renders from a place and attitude; the sun at an elevation and azimuth
  // seen from that place.
  std::vector<float> render(const Geodetic& place, double heading_deg, double pitch_deg,
                            double fov_deg, double sun_elevation_deg, double sun_azimuth_deg) {
    auto view = view_from_place(body_.shape, place, heading_deg, pitch_deg, fov_deg,
                                sun_elevation_deg, sun_azimuth_deg);
    renderer_->render(view.camera, view.sun_dir_body, 10.0);
    return renderer_->read_hdr();
  }

  // Pixel (x, y) with y counted from the top of the image.
  static glm::vec3 at(const std::vector<float>& hdr, int x, int y_from_top) {
    size_t i = (size_t(kSize - 1 - y_from_top) * kSize + size_t(x)) * 4;
    return {hdr[i], hdr[i + 1], hdr[i + 2]};
  }
  static float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

  std::unique_ptr<GlContext> context_;
  Body body_;
  std::unique_ptr<FrameRenderer> renderer_;
};

TEST_F(FrameGLTest, GroundDaySkyIsBlueAtZenithAndBrighterAtHorizon) {
  // Looking north and level, 90 degree field: the top row is 45 degrees up,
  // the middle is the horizon. Sun 40 degrees up behind the camera.
  auto hdr = render({glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 0.0, 90.0, 40.0, 180.0);
  glm::vec3 high = at(hdr, kSize / 2, 0);
  glm::vec3 horizon = at(hdr, kSize / 2, kSize / 2 - 2);
  EXPECT_GT(high.b, 1.3f * high.r) << "sky 45 degrees up must be blue";
  EXPECT_GT(luminance(horizon), 1.2f * luminance(high)) << "horizon brighter than the sky above";
  // Below the horizon: the lit ground, darker than the sky but not black.
  glm::vec3 ground = at(hdr, kSize / 2, kSize - 1);
  EXPECT_GT(luminance(ground), 0.0f);
  // Straight up: blue.
  auto zenith = render({glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 89.0, 10.0, 40.0, 180.0);
  glm::vec3 z = at(zenith, kSize / 2, kSize / 2);
  EXPECT_GT(z.b, z.g);
  EXPECT_GT(z.g, z.r);
  for (float v : zenith) ASSERT_TRUE(std::isfinite(v));
}

TEST_F(FrameGLTest, OrbitShowsBlackSpaceAndALitBlueLimb) {
  // 400 km up, looking 20 degrees down, which puts the horizon (19.7
  // degrees below level from that height) near the middle of the image.
  auto hdr = render({0.0, 0.0, 400e3}, 90.0, -20.0, 60.0, 30.0, 90.0);
  // Space: the top corners are black.
  EXPECT_LT(luminance(at(hdr, 0, 0)), 1e-6f);
  EXPECT_LT(luminance(at(hdr, kSize - 1, 0)), 1e-6f);
  // The planet fills the bottom and is lit.
  EXPECT_GT(luminance(at(hdr, kSize / 2, kSize - 1)), 1e-3f);
  // Down the middle column, the first bright pixel from the top is the limb
  // of the atmosphere: bluer than red.
  int limb = -1;
  for (int y = 0; y < kSize; ++y) {
    if (luminance(at(hdr, kSize / 2, y)) > 1e-3f) {
      limb = y;
      break;
    }
  }
  ASSERT_GT(limb, 4) << "limb must be below the top of the image";
  ASSERT_LT(limb, kSize - 4) << "limb must be above the bottom of the image";
  glm::vec3 c = at(hdr, kSize / 2, limb);
  EXPECT_GT(c.b, c.r) << "the thin atmosphere at the limb is blue";
}

TEST_F(FrameGLTest, NightSideIsDarkFromOrbit) {
  // Sun 30 degrees below the horizon: the ground below is in the planet's shadow.
  auto hdr = render({0.0, 0.0, 400e3}, 90.0, -60.0, 40.0, -30.0, 90.0);
  EXPECT_LT(luminance(at(hdr, kSize / 2, kSize - 1)), 1e-5f);
}

// Each pass's name in the frame's timings, by what became of it.
struct PassesBy {
  std::vector<std::string> ran, skipped;
};
PassesBy passes_by(const FrameStats& stats) {
  PassesBy by;
  for (const PassTiming& p : stats.passes) {
    if (p.skipped) by.skipped.push_back(p.pass);
    if (p.ran()) by.ran.push_back(p.pass);
  }
  return by;
}

// The Moon has no air: its frame is the surface pass and the tone map,
// with no atmosphere pass at all (not even a copy): the atmosphere's
// passes, and those of the options left off, are listed as skipped. The
// sunlit ground and black space are what it shows.
TEST(AirlessFrameGLTest, TheMoonRunsNoAtmospherePass) {
  auto context = GlContext::create_headless();
  Body moon = load_body(data_dir() / "planets" / "moon.json");
  ASSERT_FALSE(moon.has_atmosphere());
  const int width = 64, height = 48;
  FrameRenderer renderer(width, height);
  renderer.set_body(moon, std::nullopt, nullptr);
  auto view = view_from_place(moon.shape, {0.0, glm::radians(20.0), 30e3}, 90.0, -10.0, 60.0,
                              30.0, 90.0);
  FrameStats stats = renderer.render(view.camera, view.sun_dir_body, 10.0);
  PassesBy passes = passes_by(stats);
  EXPECT_EQ(passes.ran, (std::vector<std::string>{"surface", "tonemap"}));
  EXPECT_EQ(passes.skipped,
            (std::vector<std::string>{"atmosphere_tables", "fade:frame", "resolve",
                                      "terrain_shadow", "atmosphere", "clouds", "antialias", "fade",
                                      "stars", "exposure", "glare", "smooth_edges"}));
  std::vector<float> hdr = renderer.read_hdr();
  // Top row: space, black; bottom row: the sunlit ground.
  auto luminance = [&](int x, int y_from_bottom) {
    const float* p = &hdr[(size_t(y_from_bottom) * width + size_t(x)) * 4];
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
  };
  EXPECT_EQ(luminance(width / 2, height - 1), 0.0f);
  // The ground's regolith seen at a phase angle of 110 deg returns a
  // quarter of what Lambert's law did (0.0036 where it gave 0.014).
  EXPECT_GT(luminance(width / 2, 0), 0.002f);
}

// With every option on, the frame's own passes run in the graph's order
// (the technique's, raymarch's "sky", between the resolve and the edges);
// with a switch fading, the previous technique's frame comes first, each of
// its passes named "fade:...", and is laid over the new one after the
// edges.
TEST_F(FrameGLTest, EveryOptionsPassRunsInTheFramesOrder) {
  FrameOptions options;
  options.antialiasing = 4;
  options.smooth_edges = true;
  options.stars = true;
  options.glare = true;
  options.auto_exposure = true;
  renderer_->set_options(options);
  auto view = view_from_place(body_.shape, {glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0,
                              60.0, 20.0, 180.0);
  PassesBy passes = passes_by(renderer_->render(view.camera, view.sun_dir_body, 10.0));
  EXPECT_EQ(passes.ran, (std::vector<std::string>{"surface", "resolve", "sky", "antialias", "stars",
                                                  "exposure", "glare", "tonemap", "smooth_edges"}));
  // A smooth body casts no shadow; no switch fades; no clouds unless asked.
  EXPECT_EQ(passes.skipped,
            (std::vector<std::string>{"fade:frame", "terrain_shadow", "clouds", "fade"}));

  std::unique_ptr<AtmosphereTechnique> previous = make_technique("raymarch");
  previous->update(load_atmosphere(body_));
  renderer_->set_fade(previous.get(), 0.5);
  passes = passes_by(renderer_->render(view.camera, view.sun_dir_body, 10.0));
  EXPECT_EQ(passes.ran,
            (std::vector<std::string>{"fade:surface", "fade:resolve", "sky", "fade:antialias",
                                      "fade:keep", "surface", "resolve", "sky", "antialias", "fade",
                                      "stars", "exposure", "glare", "tonemap", "smooth_edges"}));
  renderer_->set_fade(nullptr, 0.0);
}

TEST(ProjectionTest, ReversedZInfiniteFarPlane) {
  glm::mat4 m = clip_from_view_reversed_z(glm::radians(60.0), 2.0, 0.1);
  auto depth = [&](float z) {
    glm::vec4 c = m * glm::vec4(0, 0, -z, 1);
    return c.z / c.w;
  };
  EXPECT_FLOAT_EQ(depth(0.1f), 1.0f);
  EXPECT_NEAR(depth(1e9f), 1e-10f, 1e-12f);
  EXPECT_GT(depth(1e9f), 0.0f);
  // Float depth keeps ~7 digits anywhere: 0.1 m and 1e9 m both resolve.
  EXPECT_NE(depth(1.0f), depth(1.0001f));
  EXPECT_NE(depth(1e8f), depth(1.0001e8f));
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// The depth channel of a capture: the distance along each pixel's ray.
// Straight down from 1 km over the smooth ellipsoid it is the height at the
// centre and the height over the cosine of the ray's angle toward the
// corners; looking up there is nothing (+inf).
TEST_F(FrameGLTest, DistanceAlongTheRayIsTheHeightStraightDown) {
  Geodetic place{glm::radians(46.5), glm::radians(8.0), 1000.0};
  auto view = view_from_place(body_.shape, place, 0.0, -90.0, 60.0, 40.0, 180.0);
  renderer_->render(view.camera, view.sun_dir_body, 10.0);
  std::vector<float> distance = renderer_->read_distance(view.camera);
  auto at = [&](int x, int y) { return distance[size_t(y) * kSize + size_t(x)]; };
  // The four pixels round the centre are half a pixel off the axis.
  double tan_half = std::tan(glm::radians(30.0));
  double off = tan_half / kSize;
  double centre = 1000.0 * std::sqrt(1.0 + 2.0 * off * off);
  EXPECT_NEAR(at(kSize / 2, kSize / 2), centre, 0.002 * centre);
  // A corner pixel's centre: (1 - 1/n) of the half-field in x and y.
  double c = tan_half * (1.0 - 1.0 / kSize);
  double corner = 1000.0 * std::sqrt(1.0 + 2.0 * c * c);
  // The ellipsoid curves away from the flat plane: a little farther.
  EXPECT_NEAR(at(0, 0), corner, 0.005 * corner);
  auto up = view_from_place(body_.shape, place, 0.0, 90.0, 60.0, 40.0, 180.0);
  renderer_->render(up.camera, up.sun_dir_body, 10.0);
  for (float d : renderer_->read_distance(up.camera)) ASSERT_TRUE(std::isinf(d) && d > 0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
