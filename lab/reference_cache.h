#pragma once
// Reference images of the canonical scenes: rendered once by the path
// tracer and kept as EXR in a cache, keyed by a hash of everything that
// changes the pixels (the model as loaded, the scene, paths per pixel,
// mode and the tracer's version), so a changed body file or a new tracer
// never serves a stale image.
//
// The cache lives in $PLANET_CACHE_DIR/reference if set, otherwise in
// $XDG_CACHE_HOME/planet/reference, otherwise ~/.cache/planet/reference.
// The references shipped in data/reference are read beside it (never
// written): a render found in either is not rendered again, and a longer
// render of a shipped view goes on from its shipped sums into the cache.
#include "atmosphere/reference/reference_render.h"
#include "core/image_io.h"
#include "lab/scene.h"

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace planet {

// Bumped whenever what the tracer converges to for the same inputs
// changes. A change that only makes it faster, or moves its tables by less
// than their own error (1e-5 in optical depth, tests/atmosphere/
// path_tracer_test.cpp), keeps the cached renders: their bits differ, their
// expectation does not.
constexpr int kReferenceVersion = 5;

std::filesystem::path reference_cache_dir();
std::filesystem::path shipped_reference_dir();  // data/reference
// Where references are looked for: the cache, then the shipped ones.
std::vector<std::filesystem::path> reference_dirs();

// 16 hex digits identifying (model, scene, paths, mode, kReferenceVersion).
std::string reference_key(const Scene& scene, const AtmosphereModel& model, const PathBudget& paths,
                          ReferenceMode mode);
// 16 hex digits identifying (model, scene, mode, kReferenceVersion): the
// renders of one view, whatever their paths.
std::string reference_view_key(const Scene& scene, const AtmosphereModel& model,
                               ReferenceMode mode);
// 16 hex digits identifying the model as loaded and the mode alone.
std::string reference_model_key(const AtmosphereModel& model, ReferenceMode mode);
std::filesystem::path reference_cache_file(const Scene& scene, const AtmosphereModel& model,
                                           const PathBudget& paths, ReferenceMode mode);

// The standard error of each pixel of a cached reference (render/
// path_tracer.h, kReplicates) sits beside it in this file.
std::filesystem::path reference_noise_file(const std::filesystem::path& reference_file);

// A render's running sums (path_tracer.h, RenderSums) sit beside it in
// this file, written at every checkpoint and kept when it is done: a
// render stopped part-way goes on from them, and a larger budget for the
// same view starts from the sums of a smaller one.
std::filesystem::path reference_sums_file(const std::filesystem::path& reference_file);

struct ReferenceRender {
  ImageRGB image;  // linear sRGB radiance, rows top-down
  ImageRGB noise;  // its standard error per pixel and channel
  // Where a render started: the sums it went on from (none when it started
  // from nothing or came from the cache), and their share of its paths.
  std::filesystem::path started_from;
  double started_share = 0;
};

// The scene's reference and its noise: read from the cache, or rendered on
// all cores (from the furthest sums there that fit) and cached. `progress`
// sees the fraction done while rendering; `cancel` (core/interrupt.h)
// stops it with ReferenceInterrupted, its last checkpoint kept.
ReferenceRender reference_render(const Scene& scene, const PathBudget& paths,
                                 ReferenceMode mode = ReferenceMode::kRgb,
                                 const std::function<void(double)>& progress = {},
                                 const std::atomic<bool>* cancel = nullptr);

// A render stopped part-way: what it kept and how to go on, as one line.
class ReferenceInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether the scene's reference at this budget is in the cache.
bool reference_cached(const Scene& scene, const PathBudget& paths, ReferenceMode mode);
// The budget of the cached reference of this view with the most paths, if
// any is cached or shipped.
std::optional<PathBudget> best_cached_budget(const Scene& scene, ReferenceMode mode);

// What rendering a reference would cost on this machine, from a short trial
// render of the same view (about two seconds, most of it the tracer's
// tables): seconds on all cores, paths in all, and the part already done
// in sums the render would go on from.
struct RenderCost {
  double seconds = 0;
  double paths = 0;
  double already_done = 0;  // fraction
  int threads = 0;
};
RenderCost estimate_reference_cost(const Scene& scene, const PathBudget& paths, ReferenceMode mode);
// "no reference of earth_noon (32x16, 4096 paths per pixel, rgb) is cached
// in DIR: rendering it takes about 3.2 min on 2 threads ..."
std::string describe_uncached_reference(const Scene& scene, const PathBudget& paths,
                                        ReferenceMode mode, const RenderCost& cost);
// The reference image alone.
ImageRGB reference_image(const Scene& scene, const PathBudget& paths,
                         ReferenceMode mode = ReferenceMode::kRgb,
                         const std::function<void(double)>& progress = {});

ImageRGB to_image_rgb(const ReferenceImage& image);

}  // namespace planet
