#pragma once
// The ground truth: a CPU volumetric path tracer in double precision over a
// spherical atmosphere (Medium) with a Lambertian ground.
//
// Per path, one channel (wavelength). Every transmittance is exact to the
// depth table's interpolation (reference/columns.h): along a segment, the
// difference of two lookups; toward the sun, one (zero inside the planet's
// shadow). On each segment of a path (the camera ray, then one per
// scattering or reflection):
// - the sun's light scattered once along it is estimated at one point,
//   drawn from a table of that light along the segment, toward a point
//   sampled uniformly on the sun disk; the sunlit ground at its end and the
//   disk itself are added with the segment's transmittance;
// - the path goes on. A segment toward space is forced to collide, the
//   path's weight taking the chance that it does; one toward the ground
//   collides or reaches the ground by that chance. The collision point is
//   drawn in proportion to transmittance times extinction, and the weight
//   takes the single-scattering albedo; the ground takes its albedo. The
//   next direction comes from the phase function or from a lobe about the
//   sun (multiple importance sampling). Below a weight of 0.1 a path goes
//   on by Russian roulette, through unlimited orders.
// The first numbers of each path (two per segment and two per turn) come
// from Owen-scrambled Sobol pairs (reference/sampling.h), so the paths of
// a pixel are stratified over where they gather the sun, collide and turn.
//
// Deterministic: each (scene seed, pixel, replicate, channel) has its own
// scrambled sequence and each path its own random stream; pixels are
// independent and their samples are summed in order, so a render has the
// same bits at any thread count.
#include "atmosphere/reference/columns.h"
#include "atmosphere/reference/medium.h"
#include "atmosphere/reference/sampling.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace planet {

enum class Projection { kPerspective, kEquirectangular };

// What the camera sees, in atmosphere space (atmosphere/atmosphere_space.h).
struct ReferenceView {
  int width = 128, height = 64;
  glm::dvec3 camera_atmo{0.0};
  glm::dvec3 sun_dir_atmo{0.0, 0.0, 1.0};
  Projection projection = Projection::kPerspective;
  // Perspective: the ray through normalised device coordinates (x, y) is
  // ray_from_ndc * (x, y, 1), as FrameRenderer builds it, one ray through
  // each pixel's centre. Equirectangular: columns of `frame` are east,
  // north, up; columns run in azimuth from north through east, rows from
  // the zenith (top) to the nadir.
  glm::dmat3 ray_from_ndc{1.0};
  glm::dmat3 frame{1.0};

  // Unit ray direction through the centre of pixel (x, y), rows top-down.
  glm::dvec3 ray_dir(int x, int y) const;
};

struct TraceOptions {
  // Scattering events a path may have before it ends; 0 = unlimited.
  // 1 gives single scattering (the quadrature test).
  int max_order = 0;
  // Radiance arriving from every direction outside the atmosphere (a
  // furnace); the sun is then left out.
  double environment_radiance = 0;
  bool sun = true;
};

// A render is the mean of two independent replicates (each its own
// scrambling of the stratified sequences), and half their difference is
// the standard error of that mean: its square's expectation is the mean's
// variance. Stratified sampling makes the spread of the paths themselves
// overstate the error, so the replicates are what measures it.
constexpr int kReplicates = 2;

// Paths per pixel: `spp` in all, spread evenly over the replicates and the
// channels; or, where `per_channel` is given, that many in each channel
// (spread over the replicates). A channel's noise falls as one over the
// square root of its paths, and the channels are traced apart, so the
// noisiest one (Earth's blue) can have more without the others paying.
struct PathBudget {
  int spp = 64;
  std::vector<int> per_channel;

  PathBudget() = default;
  PathBudget(int count) : spp(count) {}  // NOLINT: a plain count reads as one
  explicit PathBudget(std::vector<int> counts);
  // "98304" (in all) or "32768,131072,524288" (per channel); InputError
  // for anything else or a count below 1 or above 2^24.
  static PathBudget parse(const std::string& text);
  // The form parse() reads: for file names and messages.
  std::string label() const;
  // Paths per pixel in each lane, lane = replicate * channels + channel;
  // InputError where a lane would get none.
  std::vector<int> lane_paths(size_t channels) const;
  bool operator==(const PathBudget&) const = default;
};

// The running sums of a render, which make it one that can stop and go
// on: per pixel and lane, the sum of the radiance of the lane's paths
// [0, done[lane]). A path's numbers depend only on its pixel, lane and
// index, and a pixel's sums add its paths in index order, so a render that
// goes on from sums it wrote part-way, or from the sums of a smaller
// budget, ends with the same bits as one that never stopped.
struct RenderSums {
  int width = 0, height = 0;
  std::vector<int> done;    // paths traced so far, per lane
  std::vector<double> sum;  // [pixel * lanes + lane]

  // Paths traced so far per pixel, all lanes together.
  int64_t traced() const;
  // Whether a render with these paths per lane can go on from here: as
  // many lanes, and no more paths in any of them.
  bool fits(const std::vector<int>& lane_paths) const;
};

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
  uint64_t paths = 0;  // traced by this call (not those it started from)
  double seconds = 0;
};

ReferenceImage render_reference(const Medium& medium, const ReferenceView& view,
                                const ReferenceSettings& settings);

// The radiance (per nm, in the units of the solar irradiance) arriving at
// `origin` from direction -dir, in the table's channel: one path, its
// numbers from `sampler`.
double trace_path(const DepthTable& table, glm::dvec3 origin, glm::dvec3 dir,
                  const glm::dvec3& sun_dir, const TraceOptions& options,
                  reference::PathSampler& sampler);

struct RadianceEstimate {
  double mean = 0;
  double std_error = 0;
};
// `paths` paths of one channel in one direction, streams seeded from `seed`.
RadianceEstimate estimate_radiance(const ColumnTable& columns, size_t channel,
                                   const glm::dvec3& origin, const glm::dvec3& dir,
                                   const glm::dvec3& sun_dir, const TraceOptions& options,
                                   int paths, uint64_t seed);

}  // namespace planet
