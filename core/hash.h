#pragma once
// FNV-1a, 64 bit (Fowler, Noll and Vo): a fixed, portable hash of bytes for
// cache keys and seeds, which must not change between runs or builds.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace planet {

class Fnv1a {
 public:
  void bytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

inline uint64_t fnv1a(std::string_view text) {
  Fnv1a h;
  h.bytes(text.data(), text.size());
  return h.value();
}

}  // namespace planet
