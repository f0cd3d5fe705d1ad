// Tile geometry: the cube-sphere map, tile meshes and their error bounds.
#include "terrain/tile_mesh.h"
#include "terrain/cube_sphere.h"
#include "terrain/noise.h"

#include "core/data_paths.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/packing.hpp>

#include <random>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TerrainSurface load_surface_file(const std::filesystem::path& file) {
  Body body = load_body(file);
  return TerrainSurface(body.shape, parse_terrain(body));
}

TerrainSurface load_surface(const std::string& name) {
  return load_surface_file(data_dir() / "planets" / (name + ".json"));
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
  for (const char* name : {"earth", "mars", "asteroid", "eros"}) {
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

// A tile's height over the sea at (u, v) in [0, 1]^2 of its cell (i, j),
// interpolated over the two triangles of the cell as the GPU does.
double interpolated_sea(const TileMesh& tile, int i, int j, double u, double v) {
  auto h = [&](int a, int b) {
    return double(glm::unpackHalf2x16(tile.vertices[size_t(b * kTileGrid + a)].sea).x);
  };
  if (u >= v) return (1.0 - u) * h(i, j) + (u - v) * h(i + 1, j) + v * h(i + 1, j + 1);
  return (1.0 - v) * h(i, j) + (v - u) * h(i, j + 1) + u * h(i + 1, j + 1);
}

TEST(TileMeshTest, CoastlinesCrossTheTrianglesWhereTheGroundMeetsTheSea) {
  // Earth's tiles over coasts at three levels (seen from about 1000, 250
  // and 60 km): the share of the ground the triangles put on the wrong
  // side of the coast, against the share when whole vertices were sea or
  // land and their colours blended across the triangles (the coast drawn
  // in steps along the grid). The procedural Earth's coasts: the noise
  // shaped by the imagery's land mask.
  TerrainSurface earth =
      load_surface_file(project_root() / "tests/data/planets/earth_procedural.json");
  ASSERT_TRUE(earth.config().sea_level);
  const double sea_level = *earth.config().sea_level;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int level : {5, 7, 9}) {
    const int n = 1 << level;
    int coastal_tiles = 0, samples = 0, wrong = 0, wrong_by_vertex = 0;
    for (int face = 0; face < 6 && coastal_tiles < 3; ++face) {
      for (int y = n / 3; y < n && coastal_tiles < 3; y += std::max(1, n / 8)) {
        for (int x = n / 5; x < n && coastal_tiles < 3; x += std::max(1, n / 8)) {
          TileKey key{face, level, uint32_t(x), uint32_t(y)};
          // Only tiles with sea and land at a few points are built.
          int wet = 0;
          for (int k = 0; k < 16; ++k) {
            wet += earth.heights().seabed_height(cube_to_sphere(
                       face, key.s0() + key.size() * (0.1 + 0.8 * (k % 4) / 3.0),
                       key.t0() + key.size() * (0.1 + 0.8 * (k / 4) / 3.0))) < sea_level;
          }
          if (wet == 0 || wet == 16) continue;
          TileMesh tile = build_tile(earth, key);
          int sea = 0;
          for (int k = 0; k < kTileGrid * kTileGrid; ++k) {
            sea += glm::unpackHalf2x16(tile.vertices[size_t(k)].sea).x < 0.0f;
          }
          // A coast with sea and land in some measure.
          if (sea < 50 || sea > kTileGrid * kTileGrid - 50) continue;
          ++coastal_tiles;
          const double step = key.size() / (kTileGrid - 1);
          auto vertex_sea = [&](int a, int b) {
            return glm::unpackHalf2x16(tile.vertices[size_t(b * kTileGrid + a)].sea).x < 0.0f ? 1.0
                                                                                              : 0.0;
          };
          for (int sample = 0; sample < 3000; ++sample) {
            int i = int(unit(rng) * (kTileGrid - 1)), j = int(unit(rng) * (kTileGrid - 1));
            double u = unit(rng), v = unit(rng);
            bool truth =
                earth.heights().seabed_height(cube_to_sphere(
                    face, key.s0() + step * (i + u), key.t0() + step * (j + v))) < sea_level;
            ++samples;
            wrong += (interpolated_sea(tile, i, j, u, v) < 0.0) != truth;
            double blend = u >= v ? (1 - u) * vertex_sea(i, j) + (u - v) * vertex_sea(i + 1, j) +
                                        v * vertex_sea(i + 1, j + 1)
                                  : (1 - v) * vertex_sea(i, j) + (v - u) * vertex_sea(i, j + 1) +
                                        u * vertex_sea(i + 1, j + 1);
            wrong_by_vertex += (blend > 0.5) != truth;
          }
        }
      }
    }
    std::printf(
        "level %d: %d coastal tiles, ground on the wrong side of the coast: %.2f %% "
        "(by whole vertices: %.2f %%)\n",
        level, coastal_tiles, 100.0 * wrong / samples, 100.0 * wrong_by_vertex / samples);
    ASSERT_EQ(coastal_tiles, 3);
    // The finer the tiles, the more the triangles gain over whole vertices
    // (where the noise is finer than the grid, neither can draw it).
    EXPECT_LE(wrong, wrong_by_vertex);
    if (level >= 7) {
      EXPECT_LT(wrong, 0.75 * wrong_by_vertex);
    }
    if (level == 9) {
      EXPECT_LT(wrong, 0.01 * samples);
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
