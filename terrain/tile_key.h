#pragma once
// A quadtree tile: a cube face, a level and its column and row on that
// level's 2^level x 2^level grid of the face's (s, t) square.
#include <cstdint>
#include <functional>
#include <string>

namespace planet {

struct TileKey {
  int face = 0;
  int level = 0;
  uint32_t x = 0, y = 0;

  bool operator==(const TileKey&) const = default;

  TileKey child(int i) const {  // i = 0..3: (x, y) bits
    return {face, level + 1, 2 * x + uint32_t(i & 1), 2 * y + uint32_t(i >> 1)};
  }
  TileKey parent() const { return {face, level - 1, x / 2, y / 2}; }

  // The tile's square of the face, s0 <= s <= s1 and t0 <= t <= t1.
  double s0() const { return -1.0 + 2.0 * double(x) / double(1u << level); }
  double t0() const { return -1.0 + 2.0 * double(y) / double(1u << level); }
  double size() const { return 2.0 / double(1u << level); }

  uint64_t packed() const {
    return uint64_t(face) << 61 | uint64_t(level) << 55 | uint64_t(x) << 27 | uint64_t(y);
  }
  std::string name() const;  // "face/level/x/y", for messages
};

struct TileKeyHash {
  size_t operator()(const TileKey& k) const { return std::hash<uint64_t>()(k.packed()); }
};

}  // namespace planet
