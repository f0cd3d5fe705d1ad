#pragma once
// A reference render: the path tracer's paths over every pixel of a view,
// spread over the cores (core/parallel.h), chunk by chunk with a checkpoint
// of the running sums after each, so that it can stop and go on.
#include "atmosphere/reference/path_budget.h"
#include "atmosphere/reference/path_tracer.h"
#include "atmosphere/reference/render_sums.h"
#include "core/share.h"

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
  // The pixels traced: those of this share (pixel index % N == K, which
  // spreads the sky's cheap and the ground's dear rows evenly over the
  // shares). The others keep their starting sums.
  Share share;
};

// Whether a share of a render traces this pixel (index y * width + x).
inline bool share_owns_pixel(const Share& share, uint64_t pixel) {
  return pixel % uint64_t(share.count) == uint64_t(share.index);
}

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

// The image and noise of finished sums (every lane at its budget's paths,
// sums.done): what render_reference ends with, so that sums put together
// from shares give the same bits as one render.
void resolve_sums(const Medium& medium, const RenderSums& sums, ReferenceImage& image);

}  // namespace planet
