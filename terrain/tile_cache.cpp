#include "terrain/tile_cache.h"

#include "terrain/terrain_surface.h"

#include <algorithm>
#include <chrono>

namespace planet {

struct TileCache::State {
  struct Entry {
    std::shared_ptr<const TileMesh> mesh;
    uint64_t last_used = 0;
    size_t bytes = 0;  // of its vertices, whether held here or on the GPU
  };

  explicit State(const TerrainSurface& s) : surface(s) {}
  void work();

  const TerrainSurface surface;
  std::mutex mutex;
  std::condition_variable wake_workers, tile_done, worker_left;
  std::deque<TileKey> queue;
  std::unordered_map<TileKey, Entry, TileKeyHash> tiles;
  std::unordered_map<TileKey, bool, TileKeyHash> in_flight;
  size_t bytes = 0;
  uint64_t built = 0;
  bool stop = false;
  int running = 0;  // workers not yet returned
};

TileCache::TileCache(const TerrainSurface& surface, size_t budget_bytes, int workers)
    : state_(std::make_shared<State>(surface)), budget_(budget_bytes) {
  const int n = std::max(workers, 1);
  state_->running = n;
  for (int i = 0; i < n; ++i) {
    threads_.emplace_back([state = state_] { state->work(); });
  }
}

TileCache::~TileCache() {
  State& s = *state_;
  std::unique_lock lock(s.mutex);
  s.stop = true;
  s.queue.clear();
  s.wake_workers.notify_all();
  bool all_left = s.worker_left.wait_for(
      lock, std::chrono::duration<double>(kWorkerStopSeconds), [&] { return s.running == 0; });
  lock.unlock();
  for (auto& t : threads_) {
    // A worker still in its tile keeps the state alive and returns when
    // (if ever) the tile is done.
    if (all_left) {
      t.join();
    } else {
      t.detach();
    }
  }
}

void TileCache::request(const std::vector<TileKey>& keys) {
  State& s = *state_;
  {
    std::lock_guard lock(s.mutex);
    s.queue.clear();
    for (const TileKey& k : keys) {
      if (!s.tiles.count(k) && !s.in_flight.count(k)) s.queue.push_back(k);
    }
  }
  s.wake_workers.notify_all();
}

bool TileCache::resident(const TileKey& key) const {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  return s.tiles.count(key) > 0;
}

bool TileCache::lookup(const TileKey& key, ResidentTile& out) const {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  auto it = s.tiles.find(key);
  if (it == s.tiles.end()) return false;
  out = {it->second.mesh->error, it->second.mesh->heights};
  return true;
}

std::shared_ptr<const TileMesh> TileCache::use(const TileKey& key, uint64_t frame) {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  auto it = s.tiles.find(key);
  if (it == s.tiles.end()) return nullptr;
  it->second.last_used = frame;
  return it->second.mesh;
}

void TileCache::release_vertices(const TileKey& key) {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  auto it = s.tiles.find(key);
  if (it == s.tiles.end() || it->second.mesh->vertices.empty()) return;
  auto kept = std::make_shared<TileMesh>();
  kept->key = it->second.mesh->key;
  kept->center_body = it->second.mesh->center_body;
  kept->heights = it->second.mesh->heights;
  kept->error = it->second.mesh->error;
  it->second.mesh = std::move(kept);
}

std::vector<TileKey> TileCache::evict(uint64_t frame) {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  std::vector<TileKey> dropped;
  if (s.bytes <= budget_) return dropped;
  std::vector<std::pair<uint64_t, TileKey>> candidates;
  for (const auto& [key, entry] : s.tiles) {
    if (entry.last_used < frame) candidates.emplace_back(entry.last_used, key);
  }
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    // Oldest first; among equals, finest first (coarse tiles fill holes).
    return a.first != b.first ? a.first < b.first : a.second.level > b.second.level;
  });
  for (const auto& [used, key] : candidates) {
    if (s.bytes <= budget_) break;
    auto it = s.tiles.find(key);
    s.bytes -= it->second.bytes;
    s.tiles.erase(it);
    dropped.push_back(key);
  }
  return dropped;
}

std::vector<TileKey> TileCache::wait_for(const std::vector<TileKey>& keys, double timeout_s) {
  State& s = *state_;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::unique_lock lock(s.mutex);
  auto missing = [&] {
    std::vector<TileKey> m;
    for (const TileKey& k : keys) {
      if (!s.tiles.count(k)) m.push_back(k);
    }
    return m;
  };
  std::vector<TileKey> m = missing();
  while (!m.empty()) {
    if (s.tile_done.wait_until(lock, deadline) == std::cv_status::timeout) return missing();
    m = missing();
  }
  return m;
}

size_t TileCache::bytes() const {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  return s.bytes;
}

size_t TileCache::tile_count() const {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  return s.tiles.size();
}

uint64_t TileCache::tiles_built() const {
  State& s = *state_;
  std::lock_guard lock(s.mutex);
  return s.built;
}

void TileCache::State::work() {
  std::unique_lock lock(mutex);
  while (true) {
    wake_workers.wait(lock, [&] { return stop || !queue.empty(); });
    if (stop) break;
    TileKey key = queue.front();
    queue.pop_front();
    if (tiles.count(key) || in_flight.count(key)) continue;
    in_flight[key] = true;
    lock.unlock();
    auto mesh = std::make_shared<const TileMesh>(build_tile(surface, key));
    lock.lock();
    in_flight.erase(key);
    const size_t bytes_of = mesh->bytes();
    bytes += bytes_of;
    tiles[key] = Entry{std::move(mesh), 0, bytes_of};
    ++built;
    tile_done.notify_all();
  }
  --running;
  worker_left.notify_all();
}

}  // namespace planet
