#include "terrain/tile_mesh.h"

#include "terrain/cube_sphere.h"
#include "terrain/ground_material.h"
#include "terrain/surface_color.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

constexpr int N = kTileGrid;

// Alpha: 1 without a map; with one, 0.5 + half the map's cover
// (terrain.frag reads it back).
uint32_t pack_albedo(glm::vec3 c, float alpha) {
  auto u8 = [](float v) { return uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return u8(c.r) | u8(c.g) << 8 | u8(c.b) << 16 | u8(alpha) << 24;
}

// The k-th vertex along a tile's edge: 0 bottom (j = 0), 1 top
// (j = N - 1), 2 left (i = 0), 3 right (i = N - 1).
int edge_vertex(int edge, int k) {
  switch (edge) {
    case 0:
      return k;
    case 1:
      return (N - 1) * N + k;
    case 2:
      return k * N;
    default:
      return k * N + (N - 1);
  }
}

// A vertex's colour, packed with its alpha: the palette's rule, or on
// Earth's land the materials' rule on the day image's colour, whose far
// field terrain.frag draws by the same rule. The land's colours go to
// every vertex, the sea's too: terrain.frag draws the sea where the
// interpolated height over it is negative.
uint32_t vertex_albedo(const TerrainSurface& surface, const TileKey& key, int i, int j,
                       const glm::dvec3& x, double height, double slope, double latitude,
                       double spacing, bool at_sea) {
  const auto& config = surface.config();
  const double step = key.size() / (N - 1);
  CraterMarks marks;
  if (!at_sea) {
    marks = surface.heights().crater_marks(
        cube_to_sphere(key.face, key.s0() + step * i, key.t0() + step * j), spacing);
  }
  glm::vec3 albedo = surface_albedo(config.palette, height, slope, latitude, x, spacing, marks);
  float alpha = 1.0f;
  if (config.maps) alpha = 0.5f + 0.5f * float(map_cover(config.palette, height, slope, latitude));
  if (config.palette.materials && !at_sea) {
    const double over_sea = height - config.sea_level.value_or(0.0);
    const glm::dvec3 color = config.maps ? config.maps->day_color(x) : glm::dvec3(0.0);
    albedo = glm::vec3(
        materials::ground_material(slope, over_sea, latitude, color, bool(config.maps)).albedo);
    // The fields of light and shade, kilometres across.
    if (!config.palette.variation.empty()) {
      albedo = glm::min(albedo * float(albedo_variation(config.palette.variation, x, spacing)),
                        glm::vec3(1.0f));
    }
    if (config.maps) {
      alpha = 0.5f + 0.5f * float(materials::ground_image_cover(slope, over_sea, latitude));
    }
  }
  return pack_albedo(albedo, alpha);
}

// The tile's error: the surface at the midpoints of the cell edges and
// diagonals (the grid of twice the resolution, which the children will
// hold) against the midpoints of the triangle edges.
double tile_error(const TerrainSurface& surface, const TileKey& key, const BorderedGrid& grid) {
  const double s0 = key.s0(), t0 = key.t0(), step = key.size() / (N - 1);
  double error = 0.0;
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      const double mids[3][2] = {{0.5, 0.0}, {0.0, 0.5}, {0.5, 0.5}};
      const int ends[3][2] = {{1, 0}, {0, 1}, {1, 1}};
      for (int m = 0; m < 3; ++m) {
        if (i + ends[m][0] >= N || j + ends[m][1] >= N) continue;
        glm::dvec3 truth = surface.face_point(key.face, s0 + step * (i + mids[m][0]),
                                              t0 + step * (j + mids[m][1]));
        glm::dvec3 chord = 0.5 * (grid.at(i, j) + grid.at(i + ends[m][0], j + ends[m][1]));
        error = std::max(error, glm::length(truth - chord));
      }
    }
  }
  return error;
}

// Skirts: a copy of each edge pushed down, deep enough to cover the
// largest gap to a neighbour two levels coarser (its error bound) with
// room for float rounding of the two tiles' offsets.
void add_skirts(const TerrainSurface& surface, TileMesh& tile) {
  const TileKey& key = tile.key;
  const double depth =
      surface.error_bound(std::max(key.level - 2, 0)) + 0.05 * surface.grid_spacing(key.level);
  for (int edge = 0; edge < 4; ++edge) {
    for (int k = 0; k < N; ++k) {
      TileVertex v = tile.vertices[size_t(edge_vertex(edge, k))];
      glm::dvec3 x = tile.center_body + glm::dvec3(v.offset);
      glm::dvec3 down = -ellipsoid_normal(surface.shape(), x);
      // Never past half way to the centre: a shape far from its ellipsoid
      // (Eros, whose steep walls make the bound tens of km at the coarse
      // levels) would otherwise hang skirts through the body and out of
      // its far side, over the ground in front. Inside a body star-shaped
      // about its centre, a skirt that stops short of it stays hidden.
      v.offset = glm::vec3(x + std::min(depth, 0.5 * glm::length(x)) * down - tile.center_body);
      tile.vertices[size_t(N * N + edge * N + k)] = v;
    }
  }
}

}  // namespace

TileMesh build_tile(const TerrainSurface& surface, const TileKey& key) {
  TileMesh tile;
  tile.key = key;
  const double s0 = key.s0(), t0 = key.t0();
  tile.center_body = ellipsoid_point(
      surface.shape(), cube_to_sphere(key.face, s0 + 0.5 * key.size(), t0 + 0.5 * key.size()));
  // The grid with a border around it: every vertex's normal comes from
  // central differences of its neighbours, and its horizon from the
  // border's reach.
  const BorderedGrid grid = sample_grid(surface, key);
  auto at = [&](int i, int j) -> const glm::dvec3& { return grid.at(i, j); };
  auto height_at = [&](int i, int j) { return grid.height(i, j); };
  std::shared_ptr<const HorizonField> parent_far;
  if (key.level > 0) parent_far = surface.horizon_memo().far(surface, key.parent());
  TileHorizons horizons = compute_horizons(grid, key, parent_far.get());
  surface.horizon_memo().keep(key, std::make_shared<const HorizonField>(std::move(horizons.far)));
  tile.axis_i =
      glm::vec3(glm::normalize(cube_to_sphere(key.face, s0 + key.size(), t0 + 0.5 * key.size()) -
                               cube_to_sphere(key.face, s0, t0 + 0.5 * key.size())));
  tile.axis_j =
      glm::vec3(glm::normalize(cube_to_sphere(key.face, s0 + 0.5 * key.size(), t0 + key.size()) -
                               cube_to_sphere(key.face, s0 + 0.5 * key.size(), t0)));

  const auto& config = surface.config();
  tile.vertices.resize(kTileVertexCount);
  tile.heights = {1e300, -1e300};
  // The ground's height over the sea: under it, the sea's floor (the
  // grid's heights are the sea's surface there); without a sea, over the
  // datum.
  auto sea_at = [&](int i, int j) {
    return config.sea_level ? grid.seabed_height(i, j) - *config.sea_level : height_at(i, j);
  };
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      const glm::dvec3& x = at(i, j);
      glm::dvec3 normal =
          glm::normalize(glm::cross(at(i + 1, j) - at(i - 1, j), at(i, j + 1) - at(i, j - 1)));
      // Where the parent's grid puts this vertex: on the parent edge (or
      // diagonal) between the two even neighbours (an even vertex is its
      // own two).
      const int ia = i % 2 ? i - 1 : i, ib = i % 2 ? i + 1 : i;
      const int ja = j % 2 ? j - 1 : j, jb = j % 2 ? j + 1 : j;
      const glm::dvec3 target = 0.5 * (at(ia, ja) + at(ib, jb));
      const double sea = sea_at(i, j), sea_target = 0.5 * (sea_at(ia, ja) + sea_at(ib, jb));

      glm::dvec3 up = ellipsoid_normal(surface.shape(), x);
      double height = height_at(i, j);
      bool at_sea = config.sea_level && height <= *config.sea_level + 1e-3;
      double slope = 1.0 - glm::dot(normal, up), latitude = std::asin(std::clamp(up.z, -1.0, 1.0));
      const double spacing = glm::length(at(i + 1, j) - x);
      const uint32_t albedo =
          vertex_albedo(surface, key, i, j, x, height, slope, latitude, spacing, at_sea);
      TileVertex& v = tile.vertices[size_t(j * N + i)];
      v = {glm::vec3(x - tile.center_body),
           glm::vec3(target - x),
           glm::vec3(normal),
           albedo,
           glm::packHalf2x16(glm::vec2(float(sea), float(sea_target - sea))),
           {}};
      for (int k = 0; k < kHorizonDirections; ++k) {
        v.horizon[k] = encode_horizon(horizons.seen[size_t((j * N + i) * kHorizonDirections + k)]);
      }
      tile.heights.min = std::min(tile.heights.min, height);
      tile.heights.max = std::max(tile.heights.max, height);
    }
  }
  tile.error = tile_error(surface, key, grid);
  add_skirts(surface, tile);
  return tile;
}

const std::vector<uint16_t>& tile_indices() {
  static const std::vector<uint16_t> indices = [] {
    std::vector<uint16_t> idx;
    for (int j = 0; j + 1 < N; ++j) {
      for (int i = 0; i + 1 < N; ++i) {
        auto v00 = uint16_t(j * N + i), v10 = uint16_t(v00 + 1), v01 = uint16_t(v00 + N),
             v11 = uint16_t(v01 + 1);
        idx.insert(idx.end(), {v00, v10, v11, v00, v11, v01});
      }
    }
    for (int edge = 0; edge < 4; ++edge) {
      for (int k = 0; k + 1 < N; ++k) {
        auto a = uint16_t(edge_vertex(edge, k)), b = uint16_t(edge_vertex(edge, k + 1));
        auto sa = uint16_t(N * N + edge * N + k), sb = uint16_t(sa + 1);
        idx.insert(idx.end(), {a, sa, sb, a, sb, b});
      }
    }
    return idx;
  }();
  return indices;
}

}  // namespace planet
