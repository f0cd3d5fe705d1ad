// The air in a hollow below the datum (a Martian crater's floor lies up to
// 2.5 km under the atmosphere's bottom sphere): in front of such a surface
// the techniques that march the air go down to it, as a person looking
// into the crater sees its haze. A black floor 2 km below the datum, seen
// from 1 km above it, so that two thirds of each ray lie under the sphere;
// single scattering, against a fine march on the CPU through the same air
// (the bottom's density below the sphere, the sun's light through it).
#include "atmosphere/gpu/registry.h"
#include "atmosphere/math/shared_math.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "gl/texture.h"
#include "gl/timer.h"
#include "sim/body.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 64, kHeight = 32;
constexpr double kCameraHeight = 1000.0, kFloorDepth = 2000.0;
constexpr float kNear = 0.1f;

struct Scene {
  AtmosphereModel model;
  glm::dvec3 camera{0.0};
  glm::dmat3 ray_from_ndc{1.0};
  glm::dvec3 sun{0.0};
  // Per pixel (rows from the bottom): the unit ray and the distance to the
  // floor along it.
  std::vector<glm::dvec3> dir;
  std::vector<double> t_floor;
};

// Looking 30 deg down over 20 deg of height; the sun 40 deg up, to the
// side.
Scene make_scene() {
  Scene s;
  s.model = load_atmosphere(load_body(data_dir() / "planets" / "mars.json"));
  const double bottom = s.model.bottom_radius;
  s.camera = {0.0, 0.0, bottom + kCameraHeight};
  const double pitch = glm::radians(-30.0), half_fov_y = glm::radians(10.0);
  const glm::dvec3 forward(std::cos(pitch), 0.0, std::sin(pitch));
  const glm::dvec3 right(0.0, -1.0, 0.0);
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_y = std::tan(half_fov_y), tan_x = tan_y * kWidth / kHeight;
  s.ray_from_ndc = glm::dmat3(right * tan_x, up * tan_y, forward);
  s.sun =
      glm::normalize(glm::dvec3(0.0, std::cos(glm::radians(40.0)), std::sin(glm::radians(40.0))));
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      glm::dvec3 ndc((i + 0.5) / kWidth * 2.0 - 1.0, (j + 0.5) / kHeight * 2.0 - 1.0, 1.0);
      glm::dvec3 d = glm::normalize(s.ray_from_ndc * ndc);
      double t_near = 0, t_far = 0;
      EXPECT_TRUE(shared::ray_sphere(s.camera, d, bottom - kFloorDepth, t_near, t_far));
      s.dir.push_back(d);
      s.t_floor.push_back(t_near);
    }
  }
  return s;
}

// The technique's radiance over the black floor, with the floor's depth
// below the datum told (`ground_below`, metres, <= 0) or not (0).
std::vector<float> render(const Scene& s, const std::string& technique_text, float ground_below) {
  const size_t n = size_t(kWidth * kHeight);
  std::vector<float> depth(n), below(n, ground_below), black(n * 4, 0.0f);
  for (size_t p = 0; p < n; ++p) {
    const glm::dvec3 ndc((double(p % kWidth) + 0.5) / kWidth * 2.0 - 1.0,
                         (double(p / kWidth) + 0.5) / kHeight * 2.0 - 1.0, 1.0);
    const double ray_scale = glm::length(s.ray_from_ndc * ndc);
    depth[p] = float(kNear * ray_scale / s.t_floor[p]);  // reversed Z
  }
  Texture depth_texture = make_texture_2d(GL_DEPTH_COMPONENT32F, kWidth, kHeight);
  glTextureSubImage2D(depth_texture.id(), 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT,
                      depth.data());
  Texture surface = make_texture_2d(GL_RGBA32F, kWidth, kHeight);
  glTextureSubImage2D(surface.id(), 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, black.data());
  Texture below_texture = make_texture_2d(GL_R32F, kWidth, kHeight);
  glTextureSubImage2D(below_texture.id(), 0, 0, 0, kWidth, kHeight, GL_RED, GL_FLOAT, below.data());
  Texture hdr = make_texture_2d(GL_RGBA32F, kWidth, kHeight);
  Texture stencil = make_texture_2d(GL_STENCIL_INDEX8, kWidth, kHeight);
  Framebuffer target = make_framebuffer(hdr.id(), 0, stencil.id());
  const GLint zero = 0;
  glClearNamedFramebufferiv(target.id(), GL_STENCIL, 0, &zero);

  SkyFrame frame;
  frame.width = kWidth;
  frame.height = kHeight;
  frame.camera_atmo = s.camera;
  frame.atmo_ray_from_ndc = glm::mat3(s.ray_from_ndc);
  frame.sun_dir_atmo = glm::vec3(s.sun);
  frame.near = kNear;
  frame.depth_texture = depth_texture.id();
  frame.surface_texture = surface.id();
  frame.ground_below_texture = below_texture.id();
  frame.target_framebuffer = target.id();
  auto technique = make_technique(technique_text);
  technique->update(s.model);
  GpuTimer timer;
  technique->prepare(timer);
  technique->render(frame, timer);
  return read_texture_rgba32f(hdr.id(), kWidth, kHeight);
}

// Single scattering from the camera to the floor: 1000 midpoint steps, the
// sun's light marched from each through the same air (200 steps).
glm::dvec3 reference(const Scene& s, size_t p) {
  const shared::Atmosphere a = shared::to_shared(s.model);
  const glm::dvec3 d = s.dir[p];
  const double nu = glm::dot(d, s.sun);
  const double phase_r = shared::rayleigh_phase(nu), phase_m = shared::mie_phase(a, nu);
  const int steps = 1000;
  const double ds = s.t_floor[p] / steps;
  glm::dvec3 luminance(0.0), depth(0.0);
  for (int k = 0; k < steps; ++k) {
    const glm::dvec3 x = s.camera + (k + 0.5) * ds * d;
    const double r = glm::length(x), altitude = r - a.bottom_radius;
    const glm::dvec3 extinction = shared::extinction_at(a, altitude);
    const glm::dvec3 to_camera = glm::exp(-(depth + 0.5 * ds * extinction));
    depth += ds * extinction;
    const glm::dvec3 sun = shared::transmittance_to_top(a, r, glm::dot(x, s.sun) / r, 200);
    const glm::dvec3 scattering =
        a.rayleigh_scattering * shared::profile_density(a.rayleigh_density, altitude) * phase_r +
        a.mie_scattering * shared::profile_density(a.mie_density, altitude) * phase_m;
    luminance += to_camera * sun * scattering * ds;
  }
  return luminance * a.solar_irradiance;
}

struct Error {
  double mean = 0, worst = 0;  // relative, over pixels and channels
  double ratio = 0;            // mean of the technique's over the reference's
};

// Every 7th pixel: a spread of rays.
constexpr size_t kPixelStride = 7;

Error compare(const Scene& s, const std::vector<glm::dvec3>& references,
              const std::vector<float>& image) {
  Error e;
  int count = 0;
  for (size_t p = 0; p < s.dir.size(); p += kPixelStride) {
    const glm::dvec3 want = references[p / kPixelStride];
    for (int c = 0; c < 3; ++c) {
      const double got = image[p * 4 + size_t(c)];
      const double rel = got / want[c] - 1.0;
      e.mean += std::abs(rel);
      e.worst = std::max(e.worst, std::abs(rel));
      e.ratio += got / want[c];
      ++count;
    }
  }
  e.mean /= count;
  e.ratio /= count;
  return e;
}

TEST(AirBelowDatumGLTest, TheHazeInFrontOfAFloorBelowTheDatumIsMarchedDownToIt) {
  auto context = GlContext::create_headless();
  const Scene scene = make_scene();
  std::vector<glm::dvec3> references;
  for (size_t p = 0; p < scene.dir.size(); p += kPixelStride) {
    references.push_back(reference(scene, p));
  }
  for (const std::string technique :
       {"hillaire:multiple=off", "hillaire:multiple=off,path=per_pixel", "raymarch"}) {
    const Error told = compare(scene, references, render(scene, technique, float(-kFloorDepth)));
    const Error untold = compare(scene, references, render(scene, technique, 0.0f));
    std::printf(
        "%s: floor told: mean error %.2f %%, worst %.2f %%; untold (the air ending at the "
        "datum): %.0f %% of the haze\n",
        technique.c_str(), 100 * told.mean, 100 * told.worst, 100 * untold.ratio);
    EXPECT_LT(told.mean, 0.03) << technique;
    EXPECT_LT(told.worst, 0.08) << technique;
    // Without it, the two thirds of each ray below the sphere are missing.
    EXPECT_LT(untold.ratio, 0.6) << technique;
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
