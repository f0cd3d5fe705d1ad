#include "terrain/horizon.h"

#include "terrain/cube_sphere.h"

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

constexpr float kRightAngle = 1.57079633f;

// The parent's far horizon at a vertex of one of its four children: the
// child's grid is half the parent's, so its even vertices are the
// parent's and the odd ones lie between (the mean of the two or four).
float parent_angle(const HorizonField& parent, const TileKey& key, int i, int j, int k) {
  const int pi0 = (key.x & 1) * (kTileGrid - 1) + i, pj0 = (key.y & 1) * (kTileGrid - 1) + j;
  const int i0 = pi0 / 2, i1 = (pi0 + 1) / 2, j0 = pj0 / 2, j1 = (pj0 + 1) / 2;
  auto at = [&](int pi, int pj) {
    return float(parent[size_t((pj * kTileGrid + pi) * kHorizonDirections + k)]);
  };
  return 0.25f * kFarHorizonUnit * (at(i0, j0) + at(i1, j0) + at(i0, j1) + at(i1, j1));
}

}  // namespace

BorderedGrid sample_grid(const TerrainSurface& surface, const TileKey& key) {
  BorderedGrid g;
  constexpr int M = BorderedGrid::kSide;
  g.points.resize(size_t(M * M));
  g.heights.resize(size_t(M * M));
  const double s0 = key.s0(), t0 = key.t0(), step = key.size() / (kTileGrid - 1);
  const std::optional<double> sea = surface.config().sea_level;
  if (sea) g.seabed.resize(size_t(M * M));
  // The face parameter runs on past the face's edge in the border; the
  // tangent warp is smooth across (a root tile's border reaches a quarter
  // of a face beyond it, well short of the warp's pole).
  for (int j = -kHorizonReach; j < kTileGrid + kHorizonReach; ++j) {
    for (int i = -kHorizonReach; i < kTileGrid + kHorizonReach; ++i) {
      size_t n = BorderedGrid::index(i, j);
      if (sea) {
        // height() is the seabed raised to the sea: one evaluation for both.
        glm::dvec3 dir = cube_to_sphere(key.face, s0 + step * i, t0 + step * j);
        g.seabed[n] = surface.heights().seabed_height(dir);
        g.heights[n] = std::max(g.seabed[n], *sea);
        g.points[n] = surface.point_at_height(dir, g.heights[n]);
      } else {
        g.points[n] = surface.face_point(key.face, s0 + step * i, t0 + step * j, &g.heights[n]);
      }
    }
  }
  return g;
}

TileHorizons compute_horizons(const BorderedGrid& grid, const TileKey& key,
                              const HorizonField* parent_far) {
  TileHorizons h;
  h.seen.resize(size_t(kTileGrid * kTileGrid * kHorizonDirections));
  h.far.resize(h.seen.size());
  for (int j = 0; j < kTileGrid; ++j) {
    for (int i = 0; i < kTileGrid; ++i) {
      const glm::dvec3& x = grid.at(i, j);
      const glm::dvec3 up = glm::normalize(x);  // geocentric, as the shader takes it
      for (int k = 0; k < kHorizonDirections; ++k) {
        double near_sin = -1.0, far_sin = -1.0;
        for (int n = 1; n <= kHorizonReach; ++n) {
          glm::dvec3 d = grid.at(i + n * kHorizonStep[k][0], j + n * kHorizonStep[k][1]) - x;
          double sin_elevation = glm::dot(d, up) / glm::length(d);
          near_sin = std::max(near_sin, sin_elevation);
          if (2 * n >= kHorizonReach) far_sin = std::max(far_sin, sin_elevation);
        }
        float inherited = parent_far ? parent_angle(*parent_far, key, i, j, k) : -kRightAngle;
        size_t slot = size_t((j * kTileGrid + i) * kHorizonDirections + k);
        h.seen[slot] = std::max(float(std::asin(near_sin)), inherited);
        float far = std::max(float(std::asin(far_sin)), inherited);
        h.far[slot] = int16_t(std::lround(far / kFarHorizonUnit));
      }
    }
  }
  return h;
}

std::shared_ptr<const HorizonField> HorizonMemo::far(const TerrainSurface& surface,
                                                     const TileKey& key) {
  {
    std::lock_guard lock(mutex_);
    auto it = kept_.find(key);
    if (it != kept_.end()) {
      it->second.stamp = ++clock_;
      return it->second.far;
    }
  }
  std::shared_ptr<const HorizonField> parent;
  if (key.level > 0) parent = far(surface, key.parent());
  auto result = std::make_shared<const HorizonField>(
      compute_horizons(sample_grid(surface, key), key, parent.get()).far);
  keep(key, result);
  return result;
}

void HorizonMemo::keep(const TileKey& key, std::shared_ptr<const HorizonField> far) {
  std::lock_guard lock(mutex_);
  kept_[key] = {std::move(far), ++clock_};
  if (kept_.size() <= capacity_) return;
  // Over capacity: drop the least recently asked quarter.
  std::vector<uint64_t> stamps;
  stamps.reserve(kept_.size());
  for (const auto& [k, e] : kept_) stamps.push_back(e.stamp);
  auto cut = stamps.begin() + std::ptrdiff_t(kept_.size() / 4);
  std::nth_element(stamps.begin(), cut, stamps.end());
  for (auto it = kept_.begin(); it != kept_.end();) {
    it = it->second.stamp < *cut ? kept_.erase(it) : std::next(it);
  }
}

size_t HorizonMemo::size() const {
  std::lock_guard lock(mutex_);
  return kept_.size();
}

uint8_t encode_horizon(float angle) {
  float a = std::clamp(angle / kRightAngle, -1.0f, 1.0f);
  float code = 127.5f + 127.5f * std::copysign(std::sqrt(std::abs(a)), a);
  return uint8_t(std::lround(std::clamp(code, 0.0f, 255.0f)));
}

float decode_horizon(uint8_t code) {
  float q = float(code) / 127.5f - 1.0f;
  return std::copysign(q * q, q) * kRightAngle;
}

}  // namespace planet
