// Tile geometry: the cube-sphere map, tile meshes and their error bounds.
#include "terrain/tile_mesh.h"
#include "terrain/cube_sphere.h"
#include "terrain/noise.h"

#include "core/data_paths.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <random>

namespace planet {
namespace {

TerrainSurface load_surface(const std::string& name) {
  Body body = load_body(data_dir() / "planets" / (name + ".json"));
  return TerrainSurface(body.shape, parse_terrain(body));
}

TEST(CubeSphereTest, TangentWarpKeepsCellAreasWithinFactor1_5) {
  // Cells of a 64 x 64 grid on one face: the area of the spherical quad
  // approximated by its two triangles.
  constexpr int n = 64;
  double lo = 1e300, hi = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      auto p = [&](int a, int b) {
        return cube_to_sphere(0, -1.0 + 2.0 * a / n, -1.0 + 2.0 * b / n);
      };
      glm::dvec3 p00 = p(i, j), p10 = p(i + 1, j), p01 = p(i, j + 1), p11 = p(i + 1, j + 1);
      double area = 0.5 * glm::length(glm::cross(p10 - p00, p11 - p00)) +
                    0.5 * glm::length(glm::cross(p11 - p00, p01 - p00));
      lo = std::min(lo, area);
      hi = std::max(hi, area);
    }
  }
  EXPECT_LT(hi / lo, 1.5);
}

TEST(CubeSphereTest, SphereToCubeInvertsCubeToSphere) {
  for (int face = 0; face < 6; ++face) {
    for (double s : {-0.9, -0.3, 0.0, 0.5, 0.99}) {
      for (double t : {-0.99, -0.1, 0.4, 0.8}) {
        FacePoint f = sphere_to_cube(cube_to_sphere(face, s, t));
        EXPECT_EQ(f.face, face);
        EXPECT_NEAR(f.s, s, 1e-12);
        EXPECT_NEAR(f.t, t, 1e-12);
      }
    }
  }
}

TEST(NoiseTest, SlopeAndCurvatureStayWithinTheirBounds) {
  // The error bounds of every tile rest on these two constants.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  const double h = 1e-3;
  double max_slope = 0, max_curvature = 0, max_value = 0;
  for (int k = 0; k < 20000; ++k) {
    glm::dvec3 p(u(rng), u(rng), u(rng));
    glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
    double f0 = gradient_noise(p - h * d, 3), f1 = gradient_noise(p, 3),
           f2 = gradient_noise(p + h * d, 3);
    max_value = std::max(max_value, std::abs(f1));
    max_slope = std::max(max_slope, std::abs(f2 - f0) / (2 * h));
    max_curvature = std::max(max_curvature, std::abs(f2 - 2 * f1 + f0) / (h * h));
  }
  EXPECT_LE(max_value, 1.0);
  EXPECT_LT(max_slope, kNoiseMaxSlope);
  EXPECT_LT(max_curvature, kNoiseMaxCurvature);
}

TEST(TileMeshTest, OffsetsAreSmallAndEvenVerticesMatchTheParent) {
  TerrainSurface earth = load_surface("earth");
  TileKey key{2, 12, 1234, 2345};
  TileMesh tile = build_tile(earth, key);
  TileMesh parent = build_tile(earth, key.parent());
  ASSERT_EQ(tile.vertices.size(), size_t(kTileVertexCount));
  // Offsets from the tile centre stay within the tile: float keeps them
  // to a few micrometres.
  for (const TileVertex& v : tile.vertices) EXPECT_LT(glm::length(v.offset), 5e3f);
  // Even grid vertices of a child are its parent's vertices; the morph
  // puts odd ones on the parent's edges.
  const int n = kTileGrid, half = (n - 1) / 2;
  int px = int(key.x % 2) * half, py = int(key.y % 2) * half;
  for (int j = 0; j < n; j += 2) {
    for (int i = 0; i < n; i += 2) {
      glm::dvec3 c = tile.center_body + glm::dvec3(tile.vertices[size_t(j * n + i)].offset);
      glm::dvec3 p = parent.center_body +
                     glm::dvec3(parent.vertices[size_t((py + j / 2) * n + px + i / 2)].offset);
      EXPECT_LT(glm::length(c - p), 1e-3);
    }
  }
}

TEST(TileMeshTest, MeasuredErrorStaysUnderTheLevelBound) {
  // Skirts are sized by error_bound(level): check it on tiles coarse and
  // fine, on each body.
  for (const char* name : {"earth", "mars", "asteroid"}) {
    TerrainSurface s = load_surface(name);
    for (int level : {2, 6, 10, 14, 18}) {
      if (level > s.config().max_level) continue;
      uint32_t n = 1u << level;
      for (uint32_t k = 0; k < 3; ++k) {
        TileKey key{int(k) % 6, level, (n / 3 + k * 977) % n, (n / 2 + k * 331) % n};
        double measured = build_tile(s, key).error;
        EXPECT_GT(measured, 0.0);
        EXPECT_LE(measured, s.error_bound(level))
            << name << " tile " << key.name() << " bound " << s.error_bound(level);
      }
    }
  }
}

}  // namespace
}  // namespace planet
