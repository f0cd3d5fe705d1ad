// Camera-relative placement: a tile's vertices projected as the terrain
// vertex shader does it, in float, while the camera moves in 1 mm steps.
#include "terrain/tile_mesh.h"

#include "core/data_paths.h"
#include "sim/geodesy.h"
#include "terrain/cube_sphere.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 1280, kHeight = 720;

struct Projector {
  glm::dmat3 view_from_body;
  double f;  // pixels per unit of tan(angle)
  glm::dvec2 pixel(const glm::dvec3& v_view) const {
    return {0.5 * kWidth + f * v_view.x / -v_view.z, 0.5 * kHeight + f * v_view.y / -v_view.z};
  }
  glm::dvec2 pixel_f(const glm::vec3& rel_eye) const {
    glm::vec3 v = glm::mat3(view_from_body) * rel_eye;  // float, as on the GPU
    return {0.5 * kWidth + f * double(v.x / -v.z), 0.5 * kHeight + f * double(v.y / -v.z)};
  }
};

// The largest difference, over 200 steps of 1 mm and the tile's grid
// vertices in view, between the step a vertex makes on screen in float and
// the step it makes in exact arithmetic: what the motion does not explain.
double worst_unexplained_step(const TileMesh& tile, glm::dvec3 eye, const glm::dvec3& step,
                              const Projector& p, bool camera_relative) {
  // The vertices in view from the start.
  std::vector<int> in_view;
  for (int i = 0; i < kTileGrid * kTileGrid; ++i) {
    glm::dvec3 v =
        p.view_from_body * (tile.center_body + glm::dvec3(tile.vertices[size_t(i)].offset) - eye);
    glm::dvec2 px = p.pixel(v);
    if (-v.z > 0.1 && px.x >= 0 && px.y >= 0 && px.x < kWidth && px.y < kHeight)
      in_view.push_back(i);
  }
  EXPECT_GT(in_view.size(), 20u);
  double worst = 0;
  std::vector<glm::dvec2> last_f, last_d;
  for (int k = 0; k < 200; ++k, eye += step) {
    std::vector<glm::dvec2> now_f, now_d;
    glm::vec3 center_rel_eye(tile.center_body - eye);  // double subtraction, then float
    for (int i : in_view) {
      const glm::vec3& offset = tile.vertices[size_t(i)].offset;
      glm::dvec3 exact = tile.center_body + glm::dvec3(offset) - eye;
      glm::vec3 rel = camera_relative
                          ? center_rel_eye + offset
                          // Body-frame vertex and eye in float, subtracted on the GPU.
                          : glm::vec3(tile.center_body + glm::dvec3(offset)) - glm::vec3(eye);
      now_d.push_back(p.pixel(p.view_from_body * exact));
      now_f.push_back(p.pixel_f(rel));
    }
    if (!last_f.empty()) {
      for (size_t i = 0; i < now_f.size(); ++i) {
        glm::dvec2 df = now_f[i] - last_f[i], dd = now_d[i] - last_d[i];
        worst = std::max(worst, glm::length(df - dd));
      }
    }
    last_f = now_f;
    last_d = now_d;
  }
  return worst;
}

struct Case {
  double height;
  int level;
};

class PrecisionTest : public ::testing::TestWithParam<Case> {};

TEST_P(PrecisionTest, VerticesMoveSmoothlyOnlyWithCameraRelativePlacement) {
  // The procedural Earth's gentle ground under the Alps' flights: on a
  // steep slope the ground 2 m away fills the view and any step grows.
  Body body = load_body(project_root() / "tests/data/planets/earth_procedural.json");
  TerrainSurface surface(body.shape, parse_terrain(body));
  Geodesy geodesy(body.shape);
  // A tile straight below the camera, at the level the LOD draws there.
  Geodetic place{glm::radians(46.55), glm::radians(7.98), 0.0};
  glm::dvec3 ground = geodesy.body_from_geodetic(place);
  FacePoint fp = sphere_to_cube(glm::normalize(ground));
  int level = GetParam().level;
  double n = double(1u << level);
  TileKey key{fp.face, level, uint32_t((fp.s + 1) / 2 * n), uint32_t((fp.t + 1) / 2 * n)};
  TileMesh tile = build_tile(surface, key);
  double ground_height = 0;
  surface.point(glm::normalize(ground), &ground_height);
  place.height = ground_height + GetParam().height;
  // Looking straight down at the tile, moving east.
  Camera camera = geodesy.camera_at(place, 0.0, -glm::half_pi<double>(), glm::radians(60.0));
  glm::dvec3 eye = camera.pos_body;
  Projector p;
  p.view_from_body = glm::mat3_cast(glm::conjugate(camera.body_from_camera));
  p.f = 0.5 * kHeight / std::tan(0.5 * camera.vertical_fov);
  glm::dvec3 step = geodesy.body_from_enu(place)[0] * 1e-3;

  double relative = worst_unexplained_step(tile, eye, step, p, true);
  double absolute = worst_unexplained_step(tile, eye, step, p, false);
  RecordProperty("camera_relative_px", std::to_string(relative));
  RecordProperty("absolute_px", std::to_string(absolute));
  std::printf(
      "height %.0f m, level %d: unexplained step %.2e px camera-relative, %.2e px absolute\n",
      GetParam().height, level, relative, absolute);
  EXPECT_LT(relative, 0.05);
  if (GetParam().height < 100) {
    // Without camera-relative placement, float body coordinates (0.5 m
    // apart at 6400 km) make vertices jump by many pixels at 2 m.
    EXPECT_GT(absolute, 0.05);
  }
}

INSTANTIATE_TEST_SUITE_P(Heights, PrecisionTest, ::testing::Values(Case{2.0, 20}, Case{400e3, 9}),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           return param_info.param.height < 100 ? std::string("Ground2m")
                                                                : std::string("Orbit400km");
                         });

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
