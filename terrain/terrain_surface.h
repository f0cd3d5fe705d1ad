#pragma once
// The body's surface as terrain sees it: the cube-sphere on the body's
// ellipsoid, raised by a height source. Answers where a tile lies (its
// bounding sphere, its geometric error per level) without building it.
#include "terrain/terrain_config.h"
#include "terrain/tile_key.h"

#include "sim/body.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace planet {

class HorizonMemo;

// Vertices per tile edge: 32 x 32 quads.
constexpr int kTileGrid = 33;

struct TileBounds {
  glm::dvec3 center_body{0.0};  // the tile's placement centre (on the ellipsoid)
  glm::dvec3 sphere_center_body{0.0};
  double radius = 0;            // bounding sphere of everything the tile can hold
  double max_radius = 0;        // no point of the tile lies farther from the body's centre
  HeightRange heights;
};

class TerrainSurface {
 public:
  TerrainSurface(const Ellipsoid& shape, TerrainConfig config);

  const Ellipsoid& shape() const { return shape_; }
  const TerrainConfig& config() const { return config_; }
  const HeightSource& heights() const { return *config_.heights; }

  // The ground point along a unit direction, with its height.
  glm::dvec3 point(const glm::dvec3& dir_body, double* height = nullptr) const;
  // The point `height` metres over the base shape along the direction.
  glm::dvec3 point_at_height(const glm::dvec3& dir_body, double height) const;
  // Face grid point (s, t) of a face.
  glm::dvec3 face_point(int face, double s, double t, double* height = nullptr) const;

  // Bounds from the heights the tile can hold: those of its built grid
  // when given, else what the height source promises for its area.
  TileBounds bounds(const TileKey& key, const HeightRange* heights = nullptr) const;
  // The largest distance between neighbouring grid vertices of a tile of
  // this level, anywhere on the body.
  double grid_spacing(int level) const { return spacing_[size_t(level)]; }
  // A bound on the distance between a tile of this level and the surface
  // it samples: heights missed between grid vertices, every octave at its
  // worst at once, plus the ellipsoid's sag. Loose (measured tile errors
  // are 5 to 50 times smaller), so level of detail uses each tile's
  // measured error instead, and this sizes skirts.
  double error_bound(int level) const { return error_[size_t(level)]; }
  // The lowest the ground comes to the centre anywhere: culling's occluder.
  double occluder_radius() const;
  double max_radius() const;
  // Tiles' far horizons kept for their children's builds (terrain/horizon.h);
  // copies of the surface share it.
  HorizonMemo& horizon_memo() const { return *horizon_memo_; }

 private:
  Ellipsoid shape_;
  TerrainConfig config_;
  std::vector<double> spacing_, error_;
  std::shared_ptr<HorizonMemo> horizon_memo_;
};

}  // namespace planet
