#pragma once
// One tile's mesh, built on the CPU: a kTileGrid^2 grid of float offsets
// from the tile's centre (which stays in double) plus a skirt hanging from
// each edge. Each vertex also carries where it goes when the tile morphs
// into its parent (CDLOD, Strugar 2010): odd grid vertices slide onto the
// parent's triangle edges, so a tile at the far end of its range looks
// exactly like its parent and the switch between them does not pop.
#include "terrain/horizon.h"
#include "terrain/terrain_surface.h"

#include <cstdint>
#include <vector>

namespace planet {

struct TileVertex {
  glm::vec3 offset;       // position - center_body, metres
  glm::vec3 morph_delta;  // parent-grid position - position
  glm::vec3 normal;       // unit, body frame
  uint32_t albedo;        // sRGB-free linear albedo, RGBA8 (alpha: tile_mesh.cpp's pack_albedo)
  // Two halves (glm::packHalf2x16): the ground's height over the sea,
  // metres, negative under it (its floor's, not the sea's surface's), and
  // its change to the parent grid's interpolation, which morphs with the
  // position. Interpolated over the triangles, its zero is the coastline,
  // whatever the tiles' size. On a body without a sea, the height over
  // the datum: where the ground lies below the atmosphere's bottom sphere,
  // the air in front of it goes down to it (terrain.frag).
  uint32_t sea;
  // The horizon's elevation in each of kHorizonDirections directions along
  // the tile's grid (encode_horizon): where the sun is below it, the
  // vertex is in a shadow.
  uint8_t horizon[kHorizonDirections];
};
static_assert(sizeof(TileVertex) == 52);

// Vertices: the grid row by row, then skirts (bottom, top, left, right
// edges, kTileGrid each).
constexpr int kTileVertexCount = kTileGrid * kTileGrid + 4 * kTileGrid;

struct TileMesh {
  TileKey key;
  glm::dvec3 center_body{0.0};
  // Unit body-frame directions of the grid's i and j at the tile's centre:
  // the frame its vertices' horizon directions are measured in.
  glm::vec3 axis_i{1, 0, 0}, axis_j{0, 1, 0};
  std::vector<TileVertex> vertices;
  HeightRange heights;  // of the grid vertices
  // The largest distance, over the midpoints of the tile's triangle edges,
  // between its triangles and the surface there: the geometric error that
  // level of detail projects to the screen.
  double error = 0;

  size_t bytes() const { return vertices.size() * sizeof(TileVertex); }
};

TileMesh build_tile(const TerrainSurface& surface, const TileKey& key);

// Triangle list shared by every tile: grid quads split along their
// (i, j)-(i+1, j+1) diagonal, which is what morphing collapses onto the
// parent's triangles, and the skirt walls.
const std::vector<uint16_t>& tile_indices();


}  // namespace planet
