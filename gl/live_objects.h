#pragma once
// How many GL objects of each kind the program holds now: every object is
// made and deleted through the wrappers of gl/ (GlName, Program, the
// queries of GpuTimer and DepthProbe), which count here. A count that grows
// across frames that should hold steady is a leak.
#include <array>
#include <cstddef>

namespace planet {

enum class GlObjectKind { texture, buffer, framebuffer, vertex_array, program, query };
inline constexpr size_t kGlObjectKinds = 6;
const char* gl_object_kind_name(GlObjectKind kind);

struct GlObjectCounts {
  std::array<long, kGlObjectKinds> live{};
  long of(GlObjectKind kind) const { return live[size_t(kind)]; }
  long total() const {
    long sum = 0;
    for (long n : live) sum += n;
    return sum;
  }
};

// `change` objects of `kind` made (positive) or deleted (negative).
void note_gl_objects(GlObjectKind kind, long change);
GlObjectCounts live_gl_objects();

}  // namespace planet
