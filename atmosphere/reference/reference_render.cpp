#include "atmosphere/reference/reference_render.h"

#include "core/error.h"
#include "core/parallel.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>

namespace planet {

namespace {

// Where a render starts: from nothing, or from the sums it was given,
// which must be of the same size and have no more paths in any lane.
RenderSums initial_sums(const ReferenceSettings& settings, const ReferenceView& view,
                        const std::vector<int>& lane_paths) {
  const size_t lanes = lane_paths.size();
  const size_t pixels = size_t(view.width) * size_t(view.height);
  if (!settings.start) {
    RenderSums sums;
    sums.width = view.width;
    sums.height = view.height;
    sums.done.assign(lanes, 0);
    sums.sum.assign(pixels * lanes, 0.0);
    return sums;
  }
  const RenderSums& sums = *settings.start;
  if (sums.width != view.width || sums.height != view.height || sums.sum.size() != pixels * lanes ||
      !sums.fits(lane_paths)) {
    throw InputError(
        fmt::format("the sums to start from are of a {}x{} render with {} lanes, "
                    "or have more paths in a lane than {} spp give it",
                    sums.width, sums.height, sums.done.size(), settings.paths.label()));
  }
  return sums;
}

}  // namespace

ReferenceImage render_reference(const Medium& m, const ReferenceView& view,
                                const ReferenceSettings& settings) {
  const size_t channels = m.channels.size();
  const size_t lanes = kReplicates * channels;
  const std::vector<int> lane_paths = settings.paths.lane_paths(channels);
  auto start = std::chrono::steady_clock::now();
  ReferenceImage image;
  image.width = view.width;
  image.height = view.height;
  image.rgb.assign(size_t(view.width) * size_t(view.height) * 3, 0.0f);
  image.noise.assign(image.rgb.size(), 0.0f);
  glm::dvec3 camera = view.camera_atmo;
  // A camera a hair below the bottom sphere is lifted onto it, as the GPU
  // frame does (atmosphere/gpu/raymarch/raymarch_sky.frag).
  double r_min = m.bottom_radius + 1.0;
  if (glm::length(camera) < r_min) camera *= r_min / glm::length(camera);
  glm::dvec3 sun = glm::normalize(view.sun_dir_atmo);
  TraceOptions trace = settings.trace;
  trace.moon_centre_atmo = view.moon_centre_atmo;
  trace.moon_radius = view.moon_radius;
  const ColumnTable columns(m);
  std::vector<DepthTable> tables;
  for (const MediumChannel& c : m.channels) tables.emplace_back(columns, c);

  const size_t pixels = size_t(view.width) * size_t(view.height);
  RenderSums sums = initial_sums(settings, view, lane_paths);
  uint64_t total_paths = 0;
  for (int n : lane_paths) total_paths += uint64_t(n);
  const uint64_t traced_before = uint64_t(sums.traced());
  uint64_t traced = traced_before;
  const int max_chunk = std::max(settings.chunk_paths, 1);
  // The first chunk is small; later ones are sized to take about
  // checkpoint_seconds, so that an interrupted render loses little.
  int chunk = std::min(max_chunk, 256);
  double trace_seconds = 0;
  auto cancelled = [&] {
    return settings.cancel && settings.cancel->load(std::memory_order_relaxed);
  };
  // Chunk by chunk: up to `chunk` more paths in every lane of every pixel,
  // then a checkpoint.
  while (traced < total_paths) {
    if (cancelled()) throw RenderInterrupted(double(traced) / double(total_paths));
    // The sums as the last checkpoint has them: a chunk cut short is undone.
    const std::vector<double> chunk_start = settings.cancel ? sums.sum : std::vector<double>();
    auto chunk_began = std::chrono::steady_clock::now();
    std::vector<int> until(lanes);
    uint64_t chunk_total = 0;
    for (size_t lane = 0; lane < lanes; ++lane) {
      until[lane] = int(std::min<int64_t>(int64_t(sums.done[lane]) + chunk, lane_paths[lane]));
      chunk_total += uint64_t(until[lane] - sums.done[lane]);
    }
    auto trace_row = [&](int y) {
      for (int x = 0; x < view.width; ++x) {
        uint64_t pixel = uint64_t(y) * uint64_t(view.width) + uint64_t(x);
        if (!share_owns_pixel(settings.share, pixel)) continue;
        glm::dvec3 dir = view.ray_dir(x, y);
        // Lane by lane, which keeps one channel's table in the cache.
        // One lane per (replicate, channel): its own stratified sequence.
        for (size_t lane = 0; lane < lanes; ++lane) {
          const DepthTable& table = tables[lane % channels];
          uint64_t seed = reference::mix64(settings.seed ^ reference::mix64(pixel * lanes + lane));
          double& sum = sums.sum[pixel * lanes + lane];
          for (int i = sums.done[lane]; i < until[lane]; ++i) {
            if (cancelled()) return;
            reference::PathSampler sampler(seed, uint32_t(i));
            sum += trace_path(table, camera, dir, sun, trace, sampler);
          }
        }
      }
    };
    std::function<void(int)> on_rows;
    if (settings.progress) {
      on_rows = [&](int rows_done) {
        settings.progress((double(traced) + double(chunk_total) * rows_done / view.height) /
                          double(total_paths));
      };
    }
    parallel_for(view.height, settings.threads, trace_row, on_rows);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - chunk_began).count();
    if (cancelled()) {
      sums.sum = chunk_start;
      throw RenderInterrupted(double(traced) / double(total_paths));
    }
    trace_seconds += seconds;
    sums.done = until;
    traced += chunk_total;
    if (settings.checkpoint) settings.checkpoint(sums);
    double scale = std::clamp(settings.checkpoint_seconds / std::max(seconds, 1e-3), 0.25, 4.0);
    chunk = std::clamp(int(chunk * scale), 1, max_chunk);
  }
  if (settings.progress) settings.progress(1.0);

  resolve_sums(m, sums, image);
  size_t traced_pixels = 0;
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    traced_pixels += share_owns_pixel(settings.share, pixel) ? 1 : 0;
  }
  image.paths = traced_pixels * (total_paths - traced_before);
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  image.trace_seconds = trace_seconds;
  return image;
}

void resolve_sums(const Medium& m, const RenderSums& sums, ReferenceImage& image) {
  const size_t channels = m.channels.size();
  const size_t lanes = kReplicates * channels;
  const size_t pixels = size_t(sums.width) * size_t(sums.height);
  image.width = sums.width;
  image.height = sums.height;
  image.rgb.assign(pixels * 3, 0.0f);
  image.noise.assign(pixels * 3, 0.0f);
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    std::array<glm::dvec3, kReplicates> replicate{};
    for (size_t lane = 0; lane < lanes; ++lane) {
      replicate[lane / channels] +=
          sums.sum[pixel * lanes + lane] / sums.done[lane] * m.channels[lane % channels].rgb_weight;
    }
    static_assert(kReplicates == 2, "the mean and spread below are of two replicates");
    glm::dvec3 mean = 0.5 * (replicate[0] + replicate[1]);
    glm::dvec3 spread = 0.5 * glm::abs(replicate[0] - replicate[1]);
    for (int c = 0; c < 3; ++c) {
      image.rgb[3 * pixel + size_t(c)] = float(mean[c]);
      image.noise[3 * pixel + size_t(c)] = float(spread[c]);
    }
  }
}

}  // namespace planet
