#include "atmosphere/reference/path_tracer.h"

#include "atmosphere/shared_math.h"
#include "sim/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace planet {

using reference::Rng;

glm::dvec3 ReferenceView::ray_dir(int x, int y) const {
  if (projection == Projection::kPerspective) {
    // Pixel centres in normalised device coordinates; GL's rows run
    // bottom-up, these top-down.
    glm::dvec2 ndc(2.0 * (x + 0.5) / width - 1.0, 1.0 - 2.0 * (y + 0.5) / height);
    return glm::normalize(ray_from_ndc * glm::dvec3(ndc, 1.0));
  }
  double azimuth = 2.0 * reference::kPi * (x + 0.5) / width;
  double elevation = 0.5 * reference::kPi - reference::kPi * (y + 0.5) / height;
  glm::dvec3 enu(std::sin(azimuth) * std::cos(elevation), std::cos(azimuth) * std::cos(elevation),
                 std::sin(elevation));
  return glm::normalize(frame * enu);
}

namespace {

// The part of the ray o + t d inside the atmosphere: [t0, t1], ending at
// the ground when the ray meets it first.
struct Segment {
  bool inside = false;
  bool hits_ground = false;
  double t0 = 0, t1 = 0;
};

Segment atmosphere_segment(const Medium& m, const glm::dvec3& o, const glm::dvec3& d) {
  Segment s;
  double t_near, t_far;
  if (!shared::ray_sphere(o, d, m.top_radius, t_near, t_far) || t_far <= 0.0) return s;
  s.inside = true;
  s.t0 = std::max(t_near, 0.0);
  s.t1 = t_far;
  double g_near, g_far;
  // From a point on the ground going up, t_near is negative: no hit.
  if (shared::ray_sphere(o, d, m.bottom_radius, g_near, g_far) && g_near > 0.0) {
    s.hits_ground = true;
    s.t1 = std::min(s.t1, g_near);
  }
  return s;
}

double altitude_of(const Medium& m, const glm::dvec3& p) {
  return glm::length(p) - m.bottom_radius;
}

// Below this weight a path goes on by Russian roulette.
constexpr double kRouletteBelow = 0.1;
// The share of the first turn's directions drawn about the sun. It helps
// where light scattered twice is a glow round the sun and costs a little
// where it is not; measured per-path spread at 1536 paths per pixel, 0 /
// 0.15 / 0.3: Mars sunset red 3.4 / 3.2 / 3.1, green 2.4 / 1.9 / 2.1;
// Earth noon blue 0.22 / 0.25 / 0.27.
constexpr double kSunward = 0.15;

// Cells of the table that places the sun's light along a segment: 8 cost
// half of 32 at Earth noon and Mars sunset, for the same spread (measured).
constexpr int kSunCells = 8;

// The optical depth from a segment's start along it, from the depth table.
// A ray that reaches the top is measured by the depths to the top from its
// two ends; one that meets the ground, by the depths of the reversed ray,
// which rises from each of its points through the start. The depths at the
// edges of kSunCells equal cells are kept: the sun's table weighs them, and
// they bracket a collision to one cell before Newton's steps.
class SegmentDepth {
 public:
  SegmentDepth(const DepthTable& table, const glm::dvec3& start, const glm::dvec3& dir,
               double length, bool falling)
      : table_(table),
        start_(start),
        dir_(falling ? -dir : dir),
        sign_(falling ? -1.0 : 1.0),
        length_(length) {
    base_ = table_.to_top(start_, dir_);
    edges_[0] = 0.0;
    for (int i = 1; i <= kSunCells; ++i) edges_[size_t(i)] = at(edge_t(i));
    // Interpolation can make a ray's depth dip by a hair; depth only grows.
    for (int i = 1; i <= kSunCells; ++i) {
      edges_[size_t(i)] = std::max(edges_[size_t(i)], edges_[size_t(i) - 1]);
    }
  }
  double at(double t) const {
    double rest = table_.to_top(start_ + sign_ * t * dir_, dir_);
    return std::max(sign_ * (base_ - rest), 0.0);
  }
  double edge_t(int i) const { return length_ * i / kSunCells; }
  // The depth at edge_t(i).
  double edge(int i) const { return edges_[size_t(i)]; }
  double total() const { return edges_[kSunCells]; }
  // The t in [0, length] where the depth is `depth` (at most total()):
  // Newton's steps on the extinction from within the edges' cell that
  // holds it, kept inside a shrinking bracket.
  double invert(double depth) const {
    const Medium& m = table_.medium();
    int cell = 0;
    while (cell < kSunCells - 1 && edges_[size_t(cell) + 1] < depth) ++cell;
    double lo = edge_t(cell), hi = edge_t(cell + 1);
    double d0 = edges_[size_t(cell)], d1 = edges_[size_t(cell) + 1];
    double t = d1 > d0 ? lo + (hi - lo) * std::clamp((depth - d0) / (d1 - d0), 0.0, 1.0)
                       : 0.5 * (lo + hi);
    for (int i = 0; i < 100 && hi - lo > 1e-4; ++i) {
      double f = at(t) - depth;
      if (std::abs(f) < 1e-12 * (1.0 + depth)) break;
      (f < 0.0 ? lo : hi) = t;
      double sigma =
          m.at(table_.channel(), altitude_of(m, start_ + sign_ * t * dir_)).extinction();
      double next = sigma > 0.0 ? t - f / sigma : 0.5 * (lo + hi);
      t = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return t;
  }

 private:
  const DepthTable& table_;
  glm::dvec3 start_, dir_;
  double sign_, length_, base_ = 0;
  std::array<double, kSunCells + 1> edges_;
};

// Transmittance from p to the top toward `dir`; 0 through the planet.
double transmittance_to_top(const DepthTable& table, const glm::dvec3& p, const glm::dvec3& dir) {
  const Medium& m = table.medium();
  double r = glm::length(p), mu = glm::dot(p, dir) / r;
  double ratio = std::min(m.bottom_radius / r, 1.0);
  if (mu < -std::sqrt(std::max(1.0 - ratio * ratio, 0.0))) return 0.0;  // the planet's shadow
  return std::exp(-table.to_top(r, mu));
}

// The share of that table's choice spread evenly along the segment, so that
// light the table's cells missed is still reached.
constexpr double kEvenShare = 0.1;

// The sun's light scattered once along a segment toward its start,
// estimated at one point. Transmittance times extinction, which places the
// collisions, knows nothing of the sun: at a grazing sunset it would put
// the point low in the dust, where hardly any sunlight reaches, and at
// twilight in the planet's shadow. So the point is drawn from a table of
// the integrand (transmittance along the segment, times the scattering
// toward the disk's centre, times the sun's transmittance) at the cells'
// edges, and lands where the light is.
double sun_along_segment(const DepthTable& table, const glm::dvec3& start, const glm::dvec3& dir,
                         const SegmentDepth& depth, const glm::dvec3& sun_dir,
                         double cos_alpha, double u, Rng& rng) {
  const Medium& m = table.medium();
  const MediumChannel& c = table.channel();
  double nu_centre = glm::dot(dir, sun_dir);
  double p_r = shared::rayleigh_phase(nu_centre);
  double p_m = shared::cornette_shanks_phase(m.mie_g, nu_centre);
  std::array<double, kSunCells + 1> f;
  for (int i = 0; i <= kSunCells; ++i) {
    glm::dvec3 p = start + depth.edge_t(i) * dir;
    Medium::Coefficients co = m.at(c, altitude_of(m, p));
    f[size_t(i)] = std::exp(-depth.edge(i)) *
                   (co.scattering_rayleigh * p_r + co.scattering_mie * p_m) *
                   transmittance_to_top(table, p, sun_dir);
  }
  std::array<double, kSunCells> share;
  double total = 0;
  for (int i = 0; i < kSunCells; ++i) total += share[size_t(i)] = f[size_t(i)] + f[size_t(i) + 1];
  double even = total > 0.0 ? kEvenShare : 1.0;
  for (double& p : share) p = (total > 0.0 ? (1.0 - even) * p / total : 0.0) + even / kSunCells;
  int cell = 0;
  while (cell < kSunCells - 1 && u >= share[size_t(cell)]) u -= share[size_t(cell++)];
  double within = std::clamp(u / share[size_t(cell)], 0.0, 1.0);
  double cell_length = depth.edge_t(1);
  double t = (cell + within) * cell_length;
  double pdf = share[size_t(cell)] / cell_length;
  glm::dvec3 p = start + t * dir;
  Medium::Coefficients co = m.at(c, altitude_of(m, p));
  glm::dvec3 to_sun = reference::sample_cone(sun_dir, cos_alpha, rng);
  double nu = glm::dot(dir, to_sun);
  double scattering = co.scattering_rayleigh * shared::rayleigh_phase(nu) +
                      co.scattering_mie * shared::cornette_shanks_phase(m.mie_g, nu);
  return std::exp(-depth.at(t)) * scattering * c.solar_irradiance *
         transmittance_to_top(table, p, to_sun) / pdf;
}

}  // namespace

double trace_path(const DepthTable& table, glm::dvec3 origin, glm::dvec3 dir,
                  const glm::dvec3& sun_dir, const TraceOptions& options,
                  reference::PathSampler& sampler) {
  Rng& rng = sampler.rng();
  const Medium& m = table.medium();
  const MediumChannel& c = table.channel();
  const double cos_alpha = std::cos(m.sun_angular_radius);
  // Sun disk radiance E / solid angle, as the GPU frame draws it; a point
  // on the disk sampled with pdf 1 / solid angle leaves E per estimate.
  const double solid_angle = 2.0 * reference::kPi * (1.0 - cos_alpha);
  double radiance = 0, weight = 1;
  for (int order = 1;; ++order) {
    Segment s = atmosphere_segment(m, origin, dir);
    if (!s.inside) {
      radiance += weight * options.environment_radiance;
      if (order == 1 && options.sun && glm::dot(dir, sun_dir) >= cos_alpha) {
        radiance += weight * c.solar_irradiance / solid_angle;
      }
      return radiance;
    }
    glm::dvec3 start = origin + s.t0 * dir;
    double length = s.t1 - s.t0;
    SegmentDepth depth(table, start, dir, length, s.hits_ground);
    double tau = depth.total();
    double transmittance = std::exp(-tau), opacity = -std::expm1(-tau);
    // Two stratified numbers per segment: where along it the sun's light
    // is gathered, and where the path goes on from.
    glm::dvec2 segment_numbers = sampler.pair();
    if (options.sun && opacity > 0.0) {
      radiance += weight * sun_along_segment(table, start, dir, depth, sun_dir, cos_alpha,
                                             segment_numbers.x, rng);
    }
    glm::dvec3 end = start + length * dir;
    glm::dvec3 normal = glm::normalize(end);
    if (s.hits_ground && options.sun) {
      glm::dvec3 to_sun = reference::sample_cone(sun_dir, cos_alpha, rng);
      double cos_sun = glm::dot(normal, to_sun);
      if (cos_sun > 0.0) {
        radiance += weight * transmittance * c.solar_irradiance * m.ground_albedo / reference::kPi *
                    cos_sun * transmittance_to_top(table, normal * m.bottom_radius, to_sun);
      }
    }
    if (!s.hits_ground) {
      radiance += weight * transmittance * options.environment_radiance;
      if (order == 1 && options.sun && glm::dot(dir, sun_dir) >= cos_alpha) {
        radiance += weight * transmittance * c.solar_irradiance / solid_angle;
      }
    }
    if (options.max_order > 0 && order >= options.max_order) return radiance;
    // The path goes on from a collision inside the segment or from the
    // ground. Toward space, it is forced to collide, with the weight of
    // the chance that it does; toward the ground it collides or reaches
    // the ground by that chance.
    double u = segment_numbers.y;
    bool collides = true;
    if (s.hits_ground) {
      collides = u < opacity;
      if (collides) u /= opacity;
    } else {
      weight *= opacity;
    }
    glm::dvec2 turn = sampler.pair();
    if (collides) {
      if (opacity <= 0.0) return radiance;
      // In proportion to transmittance times extinction.
      double t = depth.invert(-std::log1p(-u * opacity));
      origin = start + t * dir;
      Medium::Coefficients co = m.at(c, altitude_of(m, origin));
      if (co.extinction() <= 0.0) return radiance;
      weight *= co.scattering() / co.extinction();
      // The next direction, exactly from the phase function (Rayleigh, or
      // Cornette-Shanks by rejection from Henyey-Greenstein, the first try
      // stratified), so that the weight does not change. At the first
      // turn only, a share comes from a Henyey-Greenstein lobe about the
      // sun, where the glow of dust is, and the weight is the phase over
      // the mixture's pdf (one-sample multiple importance sampling, balance
      // heuristic). At later turns such ratios would multiply, and their
      // spread with them: in dense dust paths turn hundreds of times.
      double g = m.mie_g;
      double sunward = order == 1 ? kSunward : 0.0;
      double rayleigh_share = (1.0 - sunward) * co.scattering_rayleigh / co.scattering();
      glm::dvec3 next;
      double x = turn.x;
      if (x < sunward) {
        next = reference::direction_about(sun_dir,
                                          reference::sample_henyey_greenstein_mu(g, x / sunward),
                                          2.0 * reference::kPi * turn.y);
      } else if (x < sunward + rayleigh_share) {
        next = reference::direction_about(
            dir, reference::sample_rayleigh_mu((x - sunward) / rayleigh_share),
            2.0 * reference::kPi * turn.y);
      } else {
        double first =
            std::min((x - sunward - rayleigh_share) / (1.0 - sunward - rayleigh_share), 1.0);
        next = reference::direction_about(dir, reference::sample_cornette_shanks_mu(g, first, rng),
                                          2.0 * reference::kPi * turn.y);
      }
      if (sunward > 0.0) {
        double mu = glm::dot(dir, next);
        double phase = (co.scattering_rayleigh * shared::rayleigh_phase(mu) +
                        co.scattering_mie * shared::cornette_shanks_phase(g, mu)) /
                       co.scattering();
        weight *= phase / (sunward * shared::henyey_greenstein_phase(g, glm::dot(next, sun_dir)) +
                           (1.0 - sunward) * phase);
      }
      dir = next;
    } else {
      weight *= m.ground_albedo;
      origin = normal * m.bottom_radius;
      dir = reference::sample_cosine(normal, turn);
    }
    if (weight < kRouletteBelow) {
      if (rng.uniform() * kRouletteBelow >= weight) return radiance;
      weight = kRouletteBelow;
    }
  }
}

PathBudget::PathBudget(std::vector<int> counts) : spp(0), per_channel(std::move(counts)) {
  for (int n : per_channel) spp += n;
}

PathBudget PathBudget::parse(const std::string& text) {
  std::vector<int> counts;
  size_t at = 0;
  while (true) {
    size_t comma = text.find(',', at);
    std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    // Digits only: stoll alone would take " 5" and "+5" as well.
    auto digit = [](char ch) { return ch >= '0' && ch <= '9'; };
    bool digits = !part.empty() && part.size() <= 9 && std::all_of(part.begin(), part.end(), digit);
    long long n = digits ? std::stoll(part) : -1;
    if (n < 1 || n > (1 << 24)) {
      throw InputError(fmt::format(
          "'{}' is not a path count: give paths per pixel, 1 to {}, in all (98304) or per "
          "channel (32768,131072,524288)",
          text, 1 << 24));
    }
    counts.push_back(int(n));
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return counts.size() == 1 ? PathBudget(counts[0]) : PathBudget(std::move(counts));
}

std::string PathBudget::label() const {
  if (per_channel.empty()) return std::to_string(spp);
  std::string out;
  for (int n : per_channel) out += (out.empty() ? "" : ",") + std::to_string(n);
  return out;
}

std::vector<int> PathBudget::lane_paths(size_t channels) const {
  const size_t lanes = kReplicates * channels;
  std::vector<int> out(lanes);
  if (per_channel.empty()) {
    if (spp < int(lanes)) {
      throw InputError(fmt::format("{} samples per pixel: at least {} are needed (one per "
                                   "channel in each of {} replicates)",
                                   spp, lanes, kReplicates));
    }
    // Path s of the pixel belongs to lane s % lanes.
    for (size_t lane = 0; lane < lanes; ++lane) {
      out[lane] = int((size_t(spp) - lane + lanes - 1) / lanes);
    }
    return out;
  }
  if (per_channel.size() != channels) {
    throw InputError(fmt::format("{} path counts for {} channels: give one per channel",
                                 per_channel.size(), channels));
  }
  for (size_t c = 0; c < channels; ++c) {
    if (per_channel[c] < kReplicates) {
      throw InputError(fmt::format("{} paths in channel {}: at least {} are needed (one in each "
                                   "replicate)",
                                   per_channel[c], c, kReplicates));
    }
    for (size_t r = 0; r < size_t(kReplicates); ++r) {
      out[r * channels + c] = int((size_t(per_channel[c]) - r + kReplicates - 1) / kReplicates);
    }
  }
  return out;
}

RadianceEstimate estimate_radiance(const ColumnTable& columns, size_t channel,
                                   const glm::dvec3& origin, const glm::dvec3& dir,
                                   const glm::dvec3& sun_dir, const TraceOptions& options,
                                   int paths, uint64_t seed) {
  const DepthTable table(columns, columns.medium().channels.at(channel));
  // Welford's running mean and variance.
  double mean = 0, m2 = 0;
  for (int i = 0; i < paths; ++i) {
    reference::PathSampler sampler(reference::mix64(seed ^ reference::mix64(channel)), uint32_t(i));
    double x = trace_path(table, origin, dir, sun_dir, options, sampler);
    double delta = x - mean;
    mean += delta / (i + 1);
    m2 += delta * (x - mean);
  }
  RadianceEstimate e;
  e.mean = mean;
  e.std_error = paths > 1 ? std::sqrt(m2 / (paths - 1) / paths) : 0.0;
  return e;
}

int64_t RenderSums::traced() const {
  int64_t n = 0;
  for (int d : done) n += d;
  return n;
}

bool RenderSums::fits(const std::vector<int>& lane_paths) const {
  if (done.size() != lane_paths.size()) return false;
  for (size_t lane = 0; lane < done.size(); ++lane) {
    if (done[lane] < 0 || done[lane] > lane_paths[lane]) return false;
  }
  return true;
}

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
  if (sums.width != view.width || sums.height != view.height ||
      sums.sum.size() != pixels * lanes || !sums.fits(lane_paths)) {
    throw InputError(fmt::format("the sums to start from are of a {}x{} render with {} lanes, "
                                 "or have more paths in a lane than {} spp give it",
                                 sums.width, sums.height, sums.done.size(),
                                 settings.paths.label()));
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
  const ColumnTable columns(m);
  std::vector<DepthTable> tables;
  for (const MediumChannel& c : m.channels) tables.emplace_back(columns, c);

  const size_t pixels = size_t(view.width) * size_t(view.height);
  RenderSums sums = initial_sums(settings, view, lane_paths);
  uint64_t total_paths = 0;
  for (int n : lane_paths) total_paths += uint64_t(n);
  const uint64_t traced_before = uint64_t(sums.traced());
  uint64_t traced = traced_before;
  const int chunk = std::max(settings.chunk_paths, 1);
  int threads = settings.threads > 0 ? settings.threads
                                     : std::max(1, int(std::thread::hardware_concurrency()));
  // Chunk by chunk: up to `chunk` more paths in every lane of every pixel,
  // then a checkpoint.
  while (traced < total_paths) {
    std::vector<int> until(lanes);
    uint64_t chunk_total = 0;
    for (size_t lane = 0; lane < lanes; ++lane) {
      until[lane] = int(std::min<int64_t>(int64_t(sums.done[lane]) + chunk, lane_paths[lane]));
      chunk_total += uint64_t(until[lane] - sums.done[lane]);
    }
    std::atomic<int> next_row{0}, rows_done{0};
    auto work = [&] {
      for (int y = next_row++; y < view.height; y = next_row++) {
        for (int x = 0; x < view.width; ++x) {
          uint64_t pixel = uint64_t(y) * uint64_t(view.width) + uint64_t(x);
          glm::dvec3 dir = view.ray_dir(x, y);
          // Lane by lane, which keeps one channel's table in the cache.
          // One lane per (replicate, channel): its own stratified sequence.
          for (size_t lane = 0; lane < lanes; ++lane) {
            const DepthTable& table = tables[lane % channels];
            uint64_t seed =
                reference::mix64(settings.seed ^ reference::mix64(pixel * lanes + lane));
            double& sum = sums.sum[pixel * lanes + lane];
            for (int i = sums.done[lane]; i < until[lane]; ++i) {
              reference::PathSampler sampler(seed, uint32_t(i));
              sum += trace_path(table, camera, dir, sun, settings.trace, sampler);
            }
          }
        }
        ++rows_done;
      }
    };
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i) pool.emplace_back(work);
    if (settings.progress) {
      while (rows_done.load() < view.height) {
        settings.progress((double(traced) + double(chunk_total) * rows_done.load() / view.height) /
                          double(total_paths));
        std::this_thread::sleep_for(std::chrono::milliseconds(250));
      }
    }
    for (auto& t : pool) t.join();
    sums.done = until;
    traced += chunk_total;
    if (settings.checkpoint) settings.checkpoint(sums);
  }
  if (settings.progress) settings.progress(1.0);

  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    std::array<glm::dvec3, kReplicates> replicate{};
    for (size_t lane = 0; lane < lanes; ++lane) {
      replicate[lane / channels] += sums.sum[pixel * lanes + lane] / lane_paths[lane] *
                                    m.channels[lane % channels].rgb_weight;
    }
    static_assert(kReplicates == 2, "the mean and spread below are of two replicates");
    glm::dvec3 mean = 0.5 * (replicate[0] + replicate[1]);
    glm::dvec3 spread = 0.5 * glm::abs(replicate[0] - replicate[1]);
    for (int c = 0; c < 3; ++c) {
      image.rgb[3 * pixel + size_t(c)] = float(mean[c]);
      image.noise[3 * pixel + size_t(c)] = float(spread[c]);
    }
  }
  image.paths = pixels * (total_paths - traced_before);
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace planet
