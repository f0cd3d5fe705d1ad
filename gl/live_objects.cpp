#include "gl/live_objects.h"

#include <atomic>

namespace planet {

namespace {
// Contexts may live on more than one thread (tests), hence atomics.
std::array<std::atomic<long>, kGlObjectKinds> live_counts{};
}  // namespace

const char* gl_object_kind_name(GlObjectKind kind) {
  static constexpr const char* names[kGlObjectKinds] = {"textures", "buffers", "framebuffers",
                                                        "vertex_arrays", "programs", "queries"};
  return names[size_t(kind)];
}

void note_gl_objects(GlObjectKind kind, long change) {
  live_counts[size_t(kind)].fetch_add(change, std::memory_order_relaxed);
}

GlObjectCounts live_gl_objects() {
  GlObjectCounts counts;
  for (size_t k = 0; k < kGlObjectKinds; ++k) {
    counts.live[k] = live_counts[k].load(std::memory_order_relaxed);
  }
  return counts;
}

}  // namespace planet
