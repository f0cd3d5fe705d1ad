#include "terrain/tile_cache.h"

#include <algorithm>
#include <chrono>

namespace planet {

TileCache::TileCache(const TerrainSurface& surface, size_t budget_bytes, int workers)
    : surface_(&surface), budget_(budget_bytes) {
  for (int i = 0; i < std::max(workers, 1); ++i) threads_.emplace_back([this] { work(); });
}

TileCache::~TileCache() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_workers_.notify_all();
  for (auto& t : threads_) t.join();
}

void TileCache::request(const std::vector<TileKey>& keys) {
  {
    std::lock_guard lock(mutex_);
    queue_.clear();
    for (const TileKey& k : keys) {
      if (!tiles_.count(k) && !in_flight_.count(k)) queue_.push_back(k);
    }
  }
  wake_workers_.notify_all();
}

bool TileCache::resident(const TileKey& key) const {
  std::lock_guard lock(mutex_);
  return tiles_.count(key) > 0;
}

bool TileCache::lookup(const TileKey& key, ResidentTile& out) const {
  std::lock_guard lock(mutex_);
  auto it = tiles_.find(key);
  if (it == tiles_.end()) return false;
  out = {it->second.mesh->error, it->second.mesh->heights};
  return true;
}

std::shared_ptr<const TileMesh> TileCache::use(const TileKey& key, uint64_t frame) {
  std::lock_guard lock(mutex_);
  auto it = tiles_.find(key);
  if (it == tiles_.end()) return nullptr;
  it->second.last_used = frame;
  return it->second.mesh;
}

void TileCache::release_vertices(const TileKey& key) {
  std::lock_guard lock(mutex_);
  auto it = tiles_.find(key);
  if (it == tiles_.end() || it->second.mesh->vertices.empty()) return;
  auto kept = std::make_shared<TileMesh>();
  kept->key = it->second.mesh->key;
  kept->center_body = it->second.mesh->center_body;
  kept->heights = it->second.mesh->heights;
  kept->error = it->second.mesh->error;
  it->second.mesh = std::move(kept);
}

std::vector<TileKey> TileCache::evict(uint64_t frame) {
  std::lock_guard lock(mutex_);
  std::vector<TileKey> dropped;
  if (bytes_ <= budget_) return dropped;
  std::vector<std::pair<uint64_t, TileKey>> candidates;
  for (const auto& [key, entry] : tiles_) {
    if (entry.last_used < frame) candidates.emplace_back(entry.last_used, key);
  }
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    // Oldest first; among equals, finest first (coarse tiles fill holes).
    return a.first != b.first ? a.first < b.first : a.second.level > b.second.level;
  });
  for (const auto& [used, key] : candidates) {
    if (bytes_ <= budget_) break;
    auto it = tiles_.find(key);
    bytes_ -= it->second.bytes;
    tiles_.erase(it);
    dropped.push_back(key);
  }
  return dropped;
}

std::vector<TileKey> TileCache::wait_for(const std::vector<TileKey>& keys, double timeout_s) {
  auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::unique_lock lock(mutex_);
  auto missing = [&] {
    std::vector<TileKey> m;
    for (const TileKey& k : keys) {
      if (!tiles_.count(k)) m.push_back(k);
    }
    return m;
  };
  std::vector<TileKey> m = missing();
  while (!m.empty()) {
    if (tile_done_.wait_until(lock, deadline) == std::cv_status::timeout) return missing();
    m = missing();
  }
  return m;
}

size_t TileCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

size_t TileCache::tile_count() const {
  std::lock_guard lock(mutex_);
  return tiles_.size();
}

uint64_t TileCache::tiles_built() const {
  std::lock_guard lock(mutex_);
  return built_;
}

void TileCache::work() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_workers_.wait(lock, [&] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    TileKey key = queue_.front();
    queue_.pop_front();
    if (tiles_.count(key) || in_flight_.count(key)) continue;
    in_flight_[key] = true;
    lock.unlock();
    auto mesh = std::make_shared<const TileMesh>(build_tile(*surface_, key));
    lock.lock();
    in_flight_.erase(key);
    const size_t bytes = mesh->bytes();
    bytes_ += bytes;
    tiles_[key] = Entry{std::move(mesh), 0, bytes};
    ++built_;
    tile_done_.notify_all();
  }
}

}  // namespace planet
