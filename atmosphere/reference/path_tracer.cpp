#include "atmosphere/reference/path_tracer.h"

#include "atmosphere/shared_math.h"
#include "sim/error.h"

#include <fmt/format.h>

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

double altitude_of(const Medium& m, const glm::dvec3& p) { return glm::length(p) - m.bottom_radius; }

double free_flight(double majorant, Rng& rng) { return -std::log1p(-rng.uniform()) / majorant; }

}  // namespace

double ratio_tracking_transmittance(const Medium& m, const MediumChannel& c,
                                    const glm::dvec3& origin, const glm::dvec3& dir, Rng& rng) {
  Segment s = atmosphere_segment(m, origin, dir);
  if (!s.inside) return 1.0;
  if (s.hits_ground) return 0.0;  // the planet's shadow
  double transmittance = 1.0;
  for (double t = s.t0 + free_flight(c.majorant, rng); t < s.t1; t += free_flight(c.majorant, rng)) {
    transmittance *= 1.0 - m.at(c, altitude_of(m, origin + t * dir)).extinction() / c.majorant;
  }
  return transmittance;
}

double trace_path(const Medium& m, const MediumChannel& c, glm::dvec3 origin, glm::dvec3 dir,
                  const glm::dvec3& sun_dir, const TraceOptions& options, Rng& rng) {
  const double cos_alpha = std::cos(m.sun_angular_radius);
  // Sun disk radiance E / solid angle, as the GPU frame draws it; a point
  // on the disk sampled with pdf 1 / solid angle leaves E per estimate.
  const double solid_angle = 2.0 * reference::kPi * (1.0 - cos_alpha);
  const double majorant = c.majorant;
  double radiance = 0;
  // Each segment of the path (camera ray, then one per scattering or
  // reflection) is tracked to its end through the majorant's tentative
  // collisions. Two estimators share them:
  // - the sun's direct light scattered along the segment: at each
  //   tentative collision, with probability sigma_s / majorant, a
  //   next-event estimate weighted by the segment's transmittance so far
  //   (ratio tracking); likewise the sunlit ground at the segment's end and
  //   the sun disk itself. No path then contributes nothing merely because
  //   it met no particle (a next-flight estimator, after Novak et al. 2014).
  // - the path's continuation, by analog delta tracking: the first real
  //   collision absorbs (the path ends) or scatters (the next segment);
  //   reaching the ground, the albedo decides by roulette.
  // The continuation's vertices add only light scattered more than once,
  // so nothing is counted twice.
  for (int order = 1;; ++order) {
    Segment s = atmosphere_segment(m, origin, dir);
    if (!s.inside) {
      radiance += options.environment_radiance;
      if (order == 1 && options.sun && glm::dot(dir, sun_dir) >= cos_alpha) {
        radiance += c.solar_irradiance / solid_angle;
      }
      return radiance;
    }
    double transmittance = 1.0;  // ratio-tracked, from the segment's start
    bool decided = false, scatters = false, rayleigh_at_scatter = false;
    glm::dvec3 scatter_point(0.0);
    for (double t = s.t0 + free_flight(majorant, rng); t < s.t1; t += free_flight(majorant, rng)) {
      glm::dvec3 p = origin + t * dir;
      Medium::Coefficients k = m.at(c, altitude_of(m, p));
      if (options.sun && rng.uniform() * majorant < k.scattering()) {
        bool rayleigh = rng.uniform() * k.scattering() < k.scattering_rayleigh;
        glm::dvec3 to_sun = reference::sample_cone(sun_dir, cos_alpha, rng);
        double nu = glm::dot(dir, to_sun);
        double phase = rayleigh ? shared::rayleigh_phase(nu)
                                : shared::cornette_shanks_phase(m.mie_g, nu);
        radiance += transmittance * c.solar_irradiance * phase *
                    ratio_tracking_transmittance(m, c, p, to_sun, rng);
      }
      if (!decided) {
        double u = rng.uniform() * majorant;
        if (u < k.absorption) {
          decided = true;
        } else if (u < k.extinction()) {
          decided = scatters = true;
          scatter_point = p;
          rayleigh_at_scatter = rng.uniform() * k.scattering() < k.scattering_rayleigh;
        }
      }
      transmittance *= 1.0 - k.extinction() / majorant;
      if (decided && !options.sun) break;  // nothing more to gather here
    }
    glm::dvec3 end = origin + s.t1 * dir;
    glm::dvec3 normal = glm::normalize(end);
    if (s.hits_ground && options.sun) {
      glm::dvec3 to_sun = reference::sample_cone(sun_dir, cos_alpha, rng);
      double cos_sun = glm::dot(normal, to_sun);
      if (cos_sun > 0.0) {
        radiance += transmittance * c.solar_irradiance * m.ground_albedo / reference::kPi *
                    cos_sun * ratio_tracking_transmittance(m, c, normal * m.bottom_radius, to_sun, rng);
      }
    }
    if (!s.hits_ground && order == 1 && options.sun && glm::dot(dir, sun_dir) >= cos_alpha) {
      radiance += transmittance * c.solar_irradiance / solid_angle;
    }
    if (options.max_order > 0 && order >= options.max_order) return radiance;
    if (decided && !scatters) return radiance;  // absorbed
    if (scatters) {
      double mu = rayleigh_at_scatter ? reference::sample_rayleigh_mu(rng.uniform())
                                      : reference::sample_cornette_shanks_mu(m.mie_g, rng);
      dir = reference::direction_about(dir, mu, 2.0 * reference::kPi * rng.uniform());
      origin = scatter_point;
      continue;
    }
    if (!s.hits_ground) {
      // Escaped to space.
      return radiance + options.environment_radiance;
    }
    // Lambertian ground: roulette with the albedo, the survivor's weight
    // stays 1.
    if (rng.uniform() >= m.ground_albedo) return radiance;
    origin = normal * m.bottom_radius;
    dir = reference::sample_cosine(normal, rng);
  }
}

RadianceEstimate estimate_radiance(const Medium& m, size_t channel, const glm::dvec3& origin,
                                   const glm::dvec3& dir, const glm::dvec3& sun_dir,
                                   const TraceOptions& options, int paths, uint64_t seed) {
  // Welford's running mean and variance.
  double mean = 0, m2 = 0;
  for (int i = 0; i < paths; ++i) {
    Rng rng = Rng::for_sample(seed, channel, uint64_t(i));
    double x = trace_path(m, m.channels.at(channel), origin, dir, sun_dir, options, rng);
    double delta = x - mean;
    mean += delta / (i + 1);
    m2 += delta * (x - mean);
  }
  RadianceEstimate e;
  e.mean = mean;
  e.std_error = paths > 1 ? std::sqrt(m2 / (paths - 1) / paths) : 0.0;
  return e;
}

ReferenceImage render_reference(const Medium& m, const ReferenceView& view,
                                const ReferenceSettings& settings) {
  const size_t channels = m.channels.size();
  if (settings.spp < int(channels)) {
    throw InputError(fmt::format("{} samples per pixel: at least one per channel ({}) is needed",
                                 settings.spp, channels));
  }
  auto start = std::chrono::steady_clock::now();
  ReferenceImage image;
  image.width = view.width;
  image.height = view.height;
  image.rgb.assign(size_t(view.width) * size_t(view.height) * 3, 0.0f);
  glm::dvec3 camera = view.camera_atmo;
  // A camera a hair below the bottom sphere is lifted onto it, as the GPU
  // frame does (atmosphere/gpu/raymarch/raymarch_sky.frag).
  double r_min = m.bottom_radius + 1.0;
  if (glm::length(camera) < r_min) camera *= r_min / glm::length(camera);
  glm::dvec3 sun = glm::normalize(view.sun_dir_atmo);

  std::atomic<int> next_row{0}, rows_done{0};
  auto work = [&] {
    std::vector<double> sum(channels);
    std::vector<int> count(channels);
    for (int y = next_row++; y < view.height; y = next_row++) {
      for (int x = 0; x < view.width; ++x) {
        uint64_t pixel = uint64_t(y) * uint64_t(view.width) + uint64_t(x);
        glm::dvec3 dir = view.ray_dir(x, y);
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(count.begin(), count.end(), 0);
        for (int s = 0; s < settings.spp; ++s) {
          // Channels in turn, so each gets spp / channels paths.
          size_t c = size_t(s) % channels;
          Rng rng = Rng::for_sample(settings.seed, pixel, uint64_t(s));
          sum[c] += trace_path(m, m.channels[c], camera, dir, sun, settings.trace, rng);
          ++count[c];
        }
        glm::dvec3 rgb(0.0);
        for (size_t c = 0; c < channels; ++c) rgb += sum[c] / count[c] * m.channels[c].rgb_weight;
        float* out = &image.rgb[3 * pixel];
        out[0] = float(rgb.r);
        out[1] = float(rgb.g);
        out[2] = float(rgb.b);
      }
      ++rows_done;
    }
  };
  int threads = settings.threads > 0 ? settings.threads
                                     : std::max(1, int(std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i) pool.emplace_back(work);
  if (settings.progress) {
    while (rows_done.load() < view.height) {
      settings.progress(double(rows_done.load()) / view.height);
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
    settings.progress(1.0);
  }
  for (auto& t : pool) t.join();
  image.paths = uint64_t(view.width) * uint64_t(view.height) * uint64_t(settings.spp);
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace planet
