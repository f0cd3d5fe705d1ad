#pragma once
// A reference render: the path tracer's paths over every pixel of a view,
// spread over the cores (core/parallel.h), chunk by chunk with a checkpoint
// of the running sums after each, so that it can stop and go on.
#include "atmosphere/reference/path_budget.h"
#include "atmosphere/reference/path_tracer.h"
#include "atmosphere/reference/render_sums.h"

#include <cstdint>
#include <functional>
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
  // Paths per lane between checkpoints, and what is called at each one
  // (reference_cache writes the sums there).
  int chunk_paths = 8192;
  std::function<void(const RenderSums&)> checkpoint;
};

struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;    // linear sRGB radiance, rows top-down
  std::vector<float> noise;  // its standard error per pixel and channel
  uint64_t paths = 0;        // traced by this call (not those it started from)
  double seconds = 0;
};

ReferenceImage render_reference(const Medium& medium, const ReferenceView& view,
                                const ReferenceSettings& settings);

}  // namespace planet
