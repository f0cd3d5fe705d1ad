// The stars as a frame shows them: each bright star on the pixel the
// catalogue and the clock put it on, at its radiance dimmed by the air;
// none below the horizon or in the day sky; the automatic exposure that
// of the frame's mean luminance.
#include "atmosphere/atmosphere_inputs.h"
#include "atmosphere/atmosphere_space.h"
#include "atmosphere/gpu/registry.h"
#include "atmosphere/math/shared_math.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"
#include "sim/star_catalogue.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 256, kHeight = 128;

struct Frame {
  std::vector<float> hdr, distance;
  std::vector<uint8_t> ldr;
  double exposure = 0;
};

struct Scene {
  Body body;
  Camera camera;
  glm::dvec3 sun;
  UtcSeconds utc = 0;
};

// alps_nightfall's place and view, at `time` on 15 January 2026.
Scene alps(const std::string& time) {
  Scene s;
  // The procedural Earth, whose ground lies below this view's stars: over
  // ETOPO5 and its detail the camera stands 89 m over the Jungfraujoch and
  // the ridges around hide one of the three lowest stars.
  s.body = load_body(project_root() / "tests/data/planets/earth_procedural.json");
  Geodesy geodesy(s.body.shape);
  s.camera = geodesy.camera_at({glm::radians(46.55), glm::radians(7.98), 3200.0},
                               glm::radians(115.0), glm::radians(12.0), glm::radians(70.0));
  s.utc = parse_utc("2026-01-15T" + time + "Z", "test");
  s.sun = sun_dir_body(s.body.ephemeris, s.body.rotation, s.utc);
  return s;
}

Frame render(const Scene& scene, bool stars, bool automatic, double exposure = 8.0) {
  FrameRenderer renderer(kWidth, kHeight);
  FrameOptions options;
  options.stars = stars;
  options.auto_exposure = automatic;
  renderer.set_options(options);
  renderer.set_star_orientation(body_from_icrf(scene.body, scene.utc));
  if (scene.body.has_atmosphere()) {
    renderer.set_body(scene.body, load_atmosphere(scene.body), make_technique("hillaire"));
  } else {
    renderer.set_body(scene.body, std::nullopt, nullptr);
  }
  renderer.render(scene.camera, scene.sun, exposure);
  return {renderer.read_hdr(), renderer.read_distance(scene.camera), renderer.read_ldr(),
          renderer.last_exposure()};
}

// The pixel a direction at infinity falls on, or (-1, -1) off screen.
glm::ivec2 pixel_of(const Scene& scene, const glm::dvec3& dir_icrf) {
  glm::dvec3 v = glm::conjugate(scene.camera.body_from_camera) *
                 (body_from_icrf(scene.body, scene.utc) * dir_icrf);
  glm::vec4 clip = clip_from_view_reversed_z(scene.camera.vertical_fov, double(kWidth) / kHeight,
                                             scene.camera.near) *
                   glm::vec4(glm::vec3(v), 1.0f);
  if (clip.w <= 0) return {-1, -1};
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  glm::ivec2 p(int(std::floor((ndc.x + 1) * 0.5f * kWidth)),
               int(std::floor((ndc.y + 1) * 0.5f * kHeight)));
  if (p.x < 0 || p.y < 0 || p.x >= kWidth || p.y >= kHeight) return {-1, -1};
  return p;
}

float luminance(const std::vector<float>& rgba, size_t p) {
  return 0.2126f * rgba[p * 4] + 0.7152f * rgba[p * 4 + 1] + 0.0722f * rgba[p * 4 + 2];
}

TEST(StarsGLTest, AtNightTheBrightStarsShineWhereTheCatalogueAndClockPutThem) {
  auto context = GlContext::create_headless();
  // 18:00 UTC: the sun 19 deg down, Orion rising in the east-south-east.
  Scene night = alps("18:00:00");
  Frame on = render(night, true, true), off = render(night, true, true);
  Frame none = render(night, false, true);
  // Nothing but the stars lights a moonless night: the exposure is the
  // dark-adapted eye's, the highest there is.
  EXPECT_EQ(on.exposure, 1e4);
  EXPECT_EQ(on.ldr, off.ldr);  // the same frame twice
  // The air's transmittance along a direction, on the CPU in double.
  const AtmosphereModel model = load_atmosphere(night.body);
  const shared::Atmosphere air = shared::to_shared(model);
  const glm::dvec3 scale = atmosphere_scale(night.body.shape, model.bottom_radius);
  const glm::dvec3 eye = scale * night.camera.pos_body;
  auto transmittance_550 = [&](const glm::dvec3& dir_body) {
    glm::dvec3 d = glm::normalize(scale * dir_body);
    return shared::transmittance_to_top(air, glm::length(eye), glm::dot(eye, d) / glm::length(eye),
                                        256)
        .y;
  };
  int checked = 0;
  for (const Star& s : bright_stars()) {
    if (s.magnitude > 1.0) break;
    glm::ivec2 p = pixel_of(night, s.dir_icrf);
    if (p.x < 0) continue;
    size_t i = size_t(p.y) * kWidth + size_t(p.x);
    if (std::isfinite(on.distance[i])) continue;  // behind the ground
    ++checked;
    // Its radiance over the eye's arcminute, dimmed by the air.
    const double t = transmittance_550(body_from_icrf(night.body, night.utc) * s.dir_icrf);
    const float sun_550 = float(solar_irradiance_astm_g173(550.0));
    const float expected = float(star_radiance_per_sun(s.magnitude) * t) * sun_550;
    const float seen = on.hdr[i * 4 + 1] - none.hdr[i * 4 + 1];
    std::printf(
        "HR %d (V %.2f) at pixel (%d, %d): %.4g, expected %.4g (transmittance %.3f), "
        "display %d\n",
        s.hr, s.magnitude, p.x, p.y, seen, expected, t, on.ldr[i * 4 + 1]);
    EXPECT_NEAR(seen / expected, 1.0, 0.03) << "HR " << s.hr;
    EXPECT_GT(on.ldr[i * 4 + 1], 200) << "HR " << s.hr;
    EXPECT_LT(none.ldr[i * 4 + 1], 8) << "HR " << s.hr;
  }
  // Betelgeuse, Rigel and Procyon are in this view at 18:00.
  EXPECT_GE(checked, 3);
  // Behind the ground no star adds anything.
  for (size_t i = 0; i < on.distance.size(); ++i) {
    if (!std::isfinite(on.distance[i])) continue;
    ASSERT_EQ(on.hdr[i * 4 + 1], none.hdr[i * 4 + 1]) << "pixel " << i;
  }
}

TEST(StarsGLTest, TheDaySkyHidesThemThroughTheExposure) {
  auto context = GlContext::create_headless();
  Scene day = alps("12:00:00");
  Frame on = render(day, true, false), none = render(day, false, false);
  int differ = 0, stars_added = 0;
  for (size_t i = 0; i < on.ldr.size(); ++i) {
    differ += std::abs(int(on.ldr[i]) - int(none.ldr[i])) > 1;
  }
  for (size_t p = 0; p < size_t(kWidth * kHeight); ++p) {
    stars_added += luminance(on.hdr, p) > luminance(none.hdr, p);
  }
  std::printf("day: %d star pixels in the radiance, %d display values changed by more than 1\n",
              stars_added, differ);
  EXPECT_GT(stars_added, 50);  // they are there, in the radiance ...
  EXPECT_EQ(differ, 0);        // ... and nobody sees them.
}

TEST(StarsGLTest, AutomaticExposurePutsTheMeanLuminanceAtMiddleGrey) {
  auto context = GlContext::create_headless();
  for (const char* time : {"12:00:00", "16:40:00"}) {
    Scene scene = alps(time);
    Frame f = render(scene, true, true);
    // The shader's rule, on the CPU: every second pixel each way, each
    // capped at 1.
    double sum = 0;
    int n = 0;
    for (int y = 0; y < kHeight; y += 2) {
      for (int x = 0; x < kWidth; x += 2, ++n) {
        sum += std::clamp(double(luminance(f.hdr, size_t(y) * kWidth + size_t(x))), 0.0, 1.0);
      }
    }
    const double expected = std::clamp(0.18 / (sum / n), 0.1, 1e4);
    std::printf("%s: exposure %.4g (from the radiance: %.4g)\n", time, f.exposure, expected);
    EXPECT_NEAR(f.exposure / expected, 1.0, 1e-4) << time;
  }
}

TEST(StarsGLTest, AnAirlessSkyShowsThemUndimmed) {
  auto context = GlContext::create_headless();
  Scene moon;
  moon.body = load_body(data_dir() / "planets" / "moon.json");
  Geodesy geodesy(moon.body.shape);
  moon.utc = parse_utc("2026-06-21T12:00:00Z", "test");
  moon.sun = sun_dir_body(moon.body.ephemeris, moon.body.rotation, moon.utc);
  // From 100 km, looking up at 60 deg: nothing but space.
  moon.camera = geodesy.camera_at({0.0, glm::radians(20.0), 100000.0}, 0.0, glm::radians(60.0),
                                  glm::radians(60.0));
  Frame f = render(moon, true, true);
  EXPECT_EQ(f.exposure, 1e4);
  // Each star on the airless body's scale (per unit solar irradiance): the
  // brightest in view is its full radiance, no air between.
  float brightest = 0, expected = 0;
  for (const Star& s : bright_stars()) {
    glm::ivec2 p = pixel_of(moon, s.dir_icrf);
    if (p.x < 0) continue;
    expected = float(star_radiance_per_sun(s.magnitude));
    brightest = luminance(f.hdr, size_t(p.y) * kWidth + size_t(p.x));
    break;  // the catalogue is brightest first
  }
  ASSERT_GT(expected, 0.0f);
  EXPECT_NEAR(brightest / expected, 1.0, 1e-3);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
