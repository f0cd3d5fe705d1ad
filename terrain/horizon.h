#pragma once
// Terrain shadows by horizon mapping (Max 1988): for every grid vertex and
// eight directions along its tile's grid, the elevation angle of the
// highest ground seen that way. The sun is hidden where its elevation lies
// below the horizon in its azimuth; this holds for any sun, so tiles need no
// rebuild as the sun moves, and shadows are fixed to the ground (no acne,
// no swimming). Each tile looks kHorizonReach of its own grid steps along
// each direction; what lies farther comes from its parent's far horizon,
// which covers everything from half that reach out to the whole body
// through the parent's own ancestors. So a far ridge is sampled at the
// resolution of the level that holds it, and a vertex's horizon is a pure
// function of its tile's key: captures stay byte-identical whatever the
// cache held.
#include "terrain/terrain_surface.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace planet {

constexpr int kHorizonDirections = 8;
// Grid steps a tile looks along each direction (and the border of extra
// grid points its build samples for it).
constexpr int kHorizonReach = 4;

// Direction k runs along grid step kHorizonStep[k] = (di, dj): +i, then
// counter-clockwise in 45-degree steps seen from above.
constexpr int kHorizonStep[kHorizonDirections][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                                     {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

// A tile's grid with a border of kHorizonReach points on every side: body
// positions and heights, row by row.
struct BorderedGrid {
  static constexpr int kBorder = kHorizonReach;
  static constexpr int kSide = kTileGrid + 2 * kBorder;
  std::vector<glm::dvec3> points;
  std::vector<double> heights;
  // Where the body has a sea: the ground's heights under it
  // (HeightSource::seabed_height), which `heights` raises to the sea's.
  std::vector<double> seabed;

  // (i, j) of the tile's grid, from -kBorder to kTileGrid - 1 + kBorder.
  const glm::dvec3& at(int i, int j) const { return points[index(i, j)]; }
  double height(int i, int j) const { return heights[index(i, j)]; }
  double seabed_height(int i, int j) const { return seabed[index(i, j)]; }
  static size_t index(int i, int j) { return size_t((j + kBorder) * kSide + (i + kBorder)); }
};
BorderedGrid sample_grid(const TerrainSurface& surface, const TileKey& key);

// A tile's far horizons, kHorizonDirections per grid vertex at
// [(j * kTileGrid + i) * kHorizonDirections + k], in units of
// kFarHorizonUnit radians (17 KiB a tile).
using HorizonField = std::vector<int16_t>;
constexpr float kFarHorizonUnit = 1e-4f;

struct TileHorizons {
  // What the tile's vertices see, everything from one grid step out:
  // radians, laid out as HorizonField.
  std::vector<float> seen;
  HorizonField far;  // from kHorizonReach / 2 grid steps out, for its children
};
// `parent_far` is the parent's far horizon; null for a root tile.
TileHorizons compute_horizons(const BorderedGrid& grid, const TileKey& key,
                              const HorizonField* parent_far);

// The far horizons of tiles, kept for their children's builds, at most
// `capacity` of them (the least recently asked go first). A horizon not
// kept is computed again from its tile's grid and its parent's, so what is
// kept changes speed, never a result. Thread-safe.
class HorizonMemo {
 public:
  // A low flight's builds need the chains of a few hundred ancestors.
  explicit HorizonMemo(size_t capacity = 256) : capacity_(capacity) {}
  std::shared_ptr<const HorizonField> far(const TerrainSurface& surface, const TileKey& key);
  void keep(const TileKey& key, std::shared_ptr<const HorizonField> far);
  size_t size() const;

 private:
  struct Entry {
    std::shared_ptr<const HorizonField> far;
    uint64_t stamp = 0;
  };
  size_t capacity_;
  mutable std::mutex mutex_;
  std::unordered_map<TileKey, Entry, TileKeyHash> kept_;
  uint64_t clock_ = 0;
};

// A horizon angle to a byte and back: finer near level, where low suns
// set shadows (0.1 degree at 0.5 degrees, 0.7 degree at 20 degrees).
uint8_t encode_horizon(float angle);
float decode_horizon(uint8_t code);

}  // namespace planet
