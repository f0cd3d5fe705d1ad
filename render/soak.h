#pragma once
// The soak: a long simulated flight that goes on switching, to show that
// nothing grows. Each body in turn is flown from 2 m above its ground to
// orbit and back down, its atmosphere drawn by each technique in turn, for
// `cycles` rounds; the first round is the warm-up (every body, technique
// and table has been made once). After it, the process's resident memory
// must stay within 2 % of where it stood, the GL objects alive must not
// grow, and the terrain's tiles must stay within their cache's budget.
#include "gl/live_objects.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace planet {

struct SoakOptions {
  int frames = 10000;
  int width = 64, height = 32;
  int cycles = 10;  // rounds over the bodies, the warm-up's included
  // The first rounds: each cache and pool fills, and the allocator's heap
  // takes its shape (the first round meets each body in a heap that has not
  // yet held the others', so a body's second visit can sit a few MiB above
  // its first without anything growing after).
  int warmup_cycles = 2;
  std::vector<std::string> bodies = {"earth", "mars", "asteroid", "moon"};
  std::vector<std::string> techniques = {"hillaire", "hillaire2020", "raymarch", "oneil",
                                         "bruneton:cheap"};
  size_t terrain_cache_bytes = size_t(64) << 20;
  int sample_every = 25;      // frames between samples of memory
  double rss_tolerance = 0.02;  // of the resident memory after the warm-up
};

struct SoakSample {
  int frame = 0;
  std::string body, technique;
  double height_m = 0;
  double rss_mib = 0;
  double heap_mib = 0;   // what malloc has handed out and not had back
  double tiles_mib = 0;  // terrain tiles resident
  size_t tiles = 0;      // of them on the GPU, each with one GL buffer
  GlObjectCounts gl;
};

struct SoakResult {
  std::vector<SoakSample> samples;
  int warmup_frames = 0;
  double rss_start_mib = 0, rss_peak_mib = 0, rss_end_mib = 0;  // after the warm-up
  double rss_warmup_peak_mib = 0;                               // in it
  GlObjectCounts gl_start, gl_peak, gl_end;                   // after the warm-up
  // GL objects alive that the terrain's tile cache does not hold (its tiles
  // come and go with the view, within the cache's budget), at the end of
  // the warm-up and at most after it.
  long gl_fixed_start = 0, gl_fixed_peak = 0;
  double tiles_peak_mib = 0, tiles_budget_mib = 0;
  double wall_seconds = 0;
  bool interrupted = false;
  std::vector<std::string> failures;  // empty: it held

  nlohmann::json to_json() const;
};

// The process's resident memory, MiB (/proc/self/statm).
double resident_mib();
// The bytes malloc has handed out and not had back (glibc's mallinfo2), MiB:
// the program's live heap, without what the allocator keeps for reuse.
double heap_in_use_mib();

// Needs a current GL 4.5 context. `progress(done, total, label)` each frame;
// `stop()` is polled every frame (Ctrl-C): the soak then ends where it is,
// interrupted.
SoakResult run_soak(const SoakOptions& options,
                    const std::function<void(int, int, const std::string&)>& progress,
                    const std::function<bool()>& stop);

}  // namespace planet
