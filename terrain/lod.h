#pragma once
// Level-of-detail selection over the cube-sphere quadtree. A tile splits
// while its measured geometric error, projected at the distance of its
// bounding sphere, exceeds the pixel budget; tiles outside the view frustum or
// behind the body's horizon are dropped. Selection only walks into tiles
// that are resident: where children are missing it draws their parent and
// lists the children as wanted, so a frame never waits and never has holes.
// A tile's bounds depend on its key (and, once resident, on its grid's
// heights) alone: they are computed once and kept across frames.
#include "terrain/terrain_surface.h"

#include <functional>
#include <unordered_map>
#include <vector>

namespace planet {

struct LodView {
  glm::dvec3 eye_body{0.0};
  glm::dmat3 view_from_body{1.0};
  double tan_half_fov_y = 0.5774;  // tan(30 degrees)
  double aspect = 16.0 / 9.0;
  int height_px = 720;
  double pixel_budget = 1.0;

  // Pixels per radian at the image centre: a length l at distance d spans
  // l / d * pixels_per_radian() pixels.
  double pixels_per_radian() const { return 0.5 * height_px / tan_half_fov_y; }
};

struct SelectedTile {
  TileKey key;
  glm::dvec3 center_body{0.0};
  double distance = 0;    // eye to the bounding sphere, metres (0 when inside)
  double error_px = 0;    // the tile's error projected at `distance`
  // Morph toward the parent grid between these eye distances (CDLOD): the
  // parent's split distance is where the parent would be drawn instead.
  double morph_start = 0, morph_end = 0;
};

struct LodSelection {
  std::vector<SelectedTile> tiles;  // to draw
  std::vector<TileKey> wanted;      // not resident yet, nearest need first
  int visited = 0, culled_frustum = 0, culled_horizon = 0;
};

// What selection needs of a resident tile: its measured error and the
// heights of its grid (tighter bounds than the height source can promise).
struct ResidentTile {
  double error = 0;
  HeightRange heights;
};
// Fills `out` and returns true when the tile is resident.
using TileErrorLookup = std::function<bool(const TileKey&, ResidentTile& out)>;

class LodSelector {
 public:
  explicit LodSelector(const TerrainSurface& surface) : surface_(&surface) {}

  LodSelection select(const LodView& view, const TileErrorLookup& resident_error) const;

  // Distance under which a tile with this error splits.
  static double split_distance(double error, const LodView& view) {
    return error * view.pixels_per_radian() / view.pixel_budget;
  }

  // The culling tests, public for the tests that check they are conservative.
  bool in_frustum(const TileBounds& bounds, const LodView& view) const;
  bool above_horizon(const TileBounds& bounds, const LodView& view) const;

 private:
  void visit(const TileKey& key, const ResidentTile& tile, double parent_error,
             const LodView& view, const TileErrorLookup& resident_error, LodSelection& out) const;
  // The tile's bounds from the height source's promise, and from its
  // resident grid's heights; kept, and recomputed only for new keys.
  const TileBounds& bounds(const TileKey& key) const;
  const TileBounds& resident_bounds(const TileKey& key, const HeightRange& heights) const;

  const TerrainSurface* surface_;
  // At most kKeptBounds of each; emptied when full (a frame visits a few
  // thousand tiles).
  static constexpr size_t kKeptBounds = 1u << 16;
  mutable std::unordered_map<TileKey, TileBounds, TileKeyHash> bounds_, resident_bounds_;
};

}  // namespace planet
