#pragma once
// A reference render: the path tracer's paths over every pixel of a view,
// spread over the cores (core/parallel.h), chunk by chunk with a checkpoint
// of the running sums after each, so that it can stop and go on.
#include "atmosphere/reference/path_budget.h"
#include "atmosphere/reference/path_tracer.h"
#include "atmosphere/reference/render_sums.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

namespace planet {

struct ReferenceSettings {
  PathBudget paths;
  int threads = 0;    // 0: all cores
  uint64_t seed = 0;  // the scene's seed
  TraceOptions trace;
  // Called now and then with the fraction of paths traced.
  std::function<void(double)> progress;
  // Where the render starts: the sums of an earlier one of the same view,
  // seed and medium, with at most this budget's paths in every lane.
  const RenderSums* start = nullptr;
  // Paths per lane between checkpoints at most, the time a chunk between
  // checkpoints should take, and what is called at each one
  // (reference_cache writes the sums there).
  int chunk_paths = 8192;
  double checkpoint_seconds = 10.0;
  std::function<void(const RenderSums&)> checkpoint;
  // Set (by a SIGINT handler) to stop: the chunk in progress is undone and
  // RenderInterrupted thrown, the last checkpoint holding all that is kept.
  const std::atomic<bool>* cancel = nullptr;
};

// A render stopped by ReferenceSettings::cancel, with the share of its
// paths that its last checkpoint holds.
class RenderInterrupted : public std::runtime_error {
 public:
  explicit RenderInterrupted(double kept)
      : std::runtime_error("reference render interrupted"), kept_share(kept) {}
  double kept_share;
};

struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;    // linear sRGB radiance, rows top-down
  std::vector<float> noise;  // its standard error per pixel and channel
  uint64_t paths = 0;        // traced by this call (not those it started from)
  double seconds = 0;
  double trace_seconds = 0;  // of which tracing paths (the rest: tables)
};

ReferenceImage render_reference(const Medium& medium, const ReferenceView& view,
                                const ReferenceSettings& settings);

}  // namespace planet
