#include "atmosphere/reference/path_tracer.h"

#include "atmosphere/math/shared_math.h"
#include "core/error.h"

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
    double t =
        d1 > d0 ? lo + (hi - lo) * std::clamp((depth - d0) / (d1 - d0), 0.0, 1.0) : 0.5 * (lo + hi);
    for (int i = 0; i < 100 && hi - lo > 1e-4; ++i) {
      double f = at(t) - depth;
      if (std::abs(f) < 1e-12 * (1.0 + depth)) break;
      (f < 0.0 ? lo : hi) = t;
      double sigma = m.at(table_.channel(), altitude_of(m, start_ + sign_ * t * dir_)).extinction();
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

// The visible share of the sun's flux at p in a channel of this
// wavelength, with the Moon of `options` in front of it: the shared
// function's three channels (its limb darkening's wavelengths, sun.glsl)
// interpolated linearly in wavelength and held beyond them.
double sun_share(const TraceOptions& options, double sun_angular_radius, double wavelength_nm,
                 const glm::dvec3& p, const glm::dvec3& sun_dir) {
  glm::dvec3 share = shared::occluded_sun_fraction(
      sun_dir, sun_angular_radius, options.moon_centre_atmo - p, options.moon_radius);
  // R, G, B at 680, 550, 440 nm.
  if (wavelength_nm >= 680.0) return share.r;
  if (wavelength_nm >= 550.0) return glm::mix(share.g, share.r, (wavelength_nm - 550.0) / 130.0);
  if (wavelength_nm >= 440.0) return glm::mix(share.b, share.g, (wavelength_nm - 440.0) / 110.0);
  return share.b;
}

bool has_moon(const TraceOptions& options) { return options.moon_radius > 0.0; }

// Whether the ray o + t d meets the Moon (and so sees its dark side, not
// the sun behind it).
bool moon_hides(const TraceOptions& options, const glm::dvec3& o, const glm::dvec3& d) {
  double t_near, t_far;
  return has_moon(options) &&
         shared::ray_sphere(o - options.moon_centre_atmo, d, options.moon_radius, t_near, t_far) &&
         t_far > 0.0;
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
                         const SegmentDepth& depth, const glm::dvec3& sun_dir, double cos_alpha,
                         const TraceOptions& options, double u, Rng& rng) {
  const Medium& m = table.medium();
  const MediumChannel& c = table.channel();
  double nu_centre = glm::dot(dir, sun_dir);
  double p_r = shared::rayleigh_phase(nu_centre);
  double p_m = m.mie_phase_value(nu_centre);
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
                      co.scattering_mie * m.mie_phase_value(nu);
  double light = std::exp(-depth.at(t)) * scattering * c.solar_irradiance *
                 transmittance_to_top(table, p, to_sun) / pdf;
  if (has_moon(options))
    light *= sun_share(options, m.sun_angular_radius, c.wavelength_nm, p, sun_dir);
  return light;
}

}  // namespace

namespace {

// The direction a path goes on in after scattering at a point of
// coefficients `co`, coming along `dir`; `weight` takes the phase over the
// sampling's pdf where they differ (the first turn's sunward lobe).
glm::dvec3 scatter_direction(const Medium& m, const Medium::Coefficients& co, const glm::dvec3& dir,
                             const glm::dvec3& sun_dir, bool first_turn, glm::dvec2 turn, Rng& rng,
                             double& weight) {
  // The next direction, exactly from the phase function (Rayleigh, or
  // Cornette-Shanks by rejection from Henyey-Greenstein, the first try
  // stratified), so that the weight does not change. At the first
  // turn only, a share comes from a Henyey-Greenstein lobe about the
  // sun, where the glow of dust is, and the weight is the phase over
  // the mixture's pdf (one-sample multiple importance sampling, balance
  // heuristic). At later turns such ratios would multiply, and their
  // spread with them: in dense dust paths turn hundreds of times.
  double g = m.mie_g;
  double sunward = first_turn ? kSunward : 0.0;
  double rayleigh_share = (1.0 - sunward) * co.scattering_rayleigh / co.scattering();
  glm::dvec3 next;
  double x = turn.x;
  if (x < sunward) {
    next =
        reference::direction_about(sun_dir, reference::sample_henyey_greenstein_mu(g, x / sunward),
                                   2.0 * reference::kPi * turn.y);
  } else if (x < sunward + rayleigh_share) {
    next = reference::direction_about(dir,
                                      reference::sample_rayleigh_mu((x - sunward) / rayleigh_share),
                                      2.0 * reference::kPi * turn.y);
  } else {
    double first = std::min((x - sunward - rayleigh_share) / (1.0 - sunward - rayleigh_share), 1.0);
    double mu = m.mie_phase == MiePhase::kHenyeyGreenstein
                    ? reference::sample_henyey_greenstein_mu(g, first)
                    : reference::sample_cornette_shanks_mu(g, first, rng);
    next = reference::direction_about(dir, mu, 2.0 * reference::kPi * turn.y);
  }
  if (sunward > 0.0) {
    double mu = glm::dot(dir, next);
    double phase = (co.scattering_rayleigh * shared::rayleigh_phase(mu) +
                    co.scattering_mie * m.mie_phase_value(mu)) /
                   co.scattering();
    weight *= phase / (sunward * shared::henyey_greenstein_phase(g, glm::dot(next, sun_dir)) +
                       (1.0 - sunward) * phase);
  }
  return next;
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
      if (order == 1 && options.sun && glm::dot(dir, sun_dir) >= cos_alpha &&
          !moon_hides(options, origin, dir)) {
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
      radiance += weight * sun_along_segment(table, start, dir, depth, sun_dir, cos_alpha, options,
                                             segment_numbers.x, rng);
    }
    glm::dvec3 end = start + length * dir;
    glm::dvec3 normal = glm::normalize(end);
    const double albedo = order == 1 && options.first_ground_albedo >= 0.0
                              ? options.first_ground_albedo
                              : c.ground_albedo;
    if (s.hits_ground && options.sun) {
      glm::dvec3 to_sun = reference::sample_cone(sun_dir, cos_alpha, rng);
      double cos_sun = glm::dot(normal, to_sun);
      if (cos_sun > 0.0) {
        glm::dvec3 ground = normal * m.bottom_radius;
        double light = transmittance * c.solar_irradiance * albedo / reference::kPi * cos_sun *
                       transmittance_to_top(table, ground, to_sun);
        if (has_moon(options)) {
          light *= sun_share(options, m.sun_angular_radius, c.wavelength_nm, ground, sun_dir);
        }
        radiance += weight * light;
      }
    }
    if (!s.hits_ground) {
      radiance += weight * transmittance * options.environment_radiance;
      if (order == 1 && options.sun && glm::dot(dir, sun_dir) >= cos_alpha &&
          !moon_hides(options, origin, dir)) {
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
      dir = scatter_direction(m, co, dir, sun_dir, order == 1, turn, rng, weight);
    } else {
      weight *= albedo;
      origin = normal * m.bottom_radius;
      dir = reference::sample_cosine(normal, turn);
    }
    if (weight < kRouletteBelow) {
      if (rng.uniform() * kRouletteBelow >= weight) return radiance;
      weight = kRouletteBelow;
    }
  }
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

}  // namespace planet
