#pragma once
// Tiles built on worker threads into a cache bounded in bytes. The frame
// asks for what it wants (replacing the previous wish list, so tiles no
// longer wanted are never built), takes what is ready, and marks what it
// drew; when the cache is over budget the tiles unused for longest go
// first, never one used in the current frame.
#include "terrain/lod.h"
#include "terrain/tile_mesh.h"

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <vector>

namespace planet {

class TileCache {
 public:
  // The cache keeps its own copy of the surface (its height source shared).
  TileCache(const TerrainSurface& surface, size_t budget_bytes, int workers);
  // Stops the workers: each finishes the tile it is building. One that has
  // not within kWorkerStopSeconds is left behind (it ends with the
  // process), so that a tile that never finishes cannot hang the program.
  ~TileCache();
  static constexpr double kWorkerStopSeconds = 5.0;
  TileCache(const TileCache&) = delete;
  TileCache& operator=(const TileCache&) = delete;

  // The wish list for this frame, most wanted first; replaces the last one.
  void request(const std::vector<TileKey>& keys);
  // Whether the tile is built and in the cache.
  bool resident(const TileKey& key) const;
  // The resident tile's error and heights; false when not resident.
  bool lookup(const TileKey& key, ResidentTile& out) const;
  // The tile, marked as used in `frame`; null when not resident. Its
  // vertices are empty once released.
  std::shared_ptr<const TileMesh> use(const TileKey& key, uint64_t frame);
  // Drops the tile's vertices from memory, keeping what selection needs
  // (error, heights, centre): for a tile whose vertices now live on the
  // GPU, which evicts it with the cache. It still counts its vertices'
  // bytes against the budget, since the GPU holds them.
  void release_vertices(const TileKey& key);
  // Drops least recently used tiles, not used in `frame`, until under
  // budget. Returns the keys dropped, for a GPU mirror to drop too.
  std::vector<TileKey> evict(uint64_t frame);
  // Blocks until every key is resident or `timeout_s` passes; returns the
  // keys still missing: a tile that never finishes ends the wait.
  std::vector<TileKey> wait_for(const std::vector<TileKey>& keys, double timeout_s);

  size_t bytes() const;
  size_t tile_count() const;
  size_t budget_bytes() const { return budget_; }
  uint64_t tiles_built() const;

 private:
  // What the workers share with the cache. A worker holds it too, so that
  // one stuck in a tile that never finishes can be left behind when the
  // cache goes (~TileCache), and the program still ends.
  struct State;
  std::shared_ptr<State> state_;
  size_t budget_;
  std::vector<std::thread> threads_;
};

}  // namespace planet
