#include "terrain/procedural_height.h"

#include "terrain/craters.h"
#include "terrain/noise.h"
#include "terrain/surface_maps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace planet {

namespace {

// Per octave i: amplitude a_i = amplitude gain^i, frequency
// f_i = lacunarity^i / wavelength (cycles per metre of noise lattice).
template <typename F>
void for_each_octave(const NoiseLayer& layer, F&& f) {
  double a = layer.amplitude, freq = 1.0 / layer.wavelength;
  for (int i = 0; i < layer.octaves; ++i) {
    f(i, a, freq);
    a *= layer.gain;
    freq *= layer.lacunarity;
  }
}

double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The crater fields' bounds (terrain/craters.h).
constexpr double kCraterMaxSlope = craters::kMaxSlope;
constexpr double kCraterMaxCurvature = craters::kMaxCurvature;
constexpr double kCraterMinRadius = craters::kMinRadius, kCraterMaxRadius = craters::kMaxRadius;
constexpr double kCraterOverlap = craters::kOverlap;

// Rounding of the ridged crests, in units of the noise's range, and the
// curvature bound that follows: with r = 1 - (sqrt(g^2 + e^2) - e),
// |r''| <= (2 S^2 / e + C) f^2 and |(2 r^2)''| <= 4 (S^2 f^2 + |r''|).
constexpr double kRidgeRounding = 0.1;
constexpr double kRidgedMaxCurvature =
    4.0 * (kNoiseMaxSlope * kNoiseMaxSlope +
           2.0 * kNoiseMaxSlope * kNoiseMaxSlope / kRidgeRounding + kNoiseMaxCurvature);

// A ramp rounded over [-k, k]: 0 below, x above, a parabola between
// (slope in [0, 1], curvature 1 / (2 k)).
double soft_ramp(double x, double k) {
  if (x <= -k) return 0.0;
  if (x >= k) return x;
  return (x + k) * (x + k) / (4.0 * k);
}

// Where the map's land mask turns noise from sea to land.
constexpr double kLandEdge0 = 0.3, kLandEdge1 = 0.7;

// The craters' heights around p. Distances are taken in 3D: a centre off
// the surface gives a smaller, shallower crater where the sphere cuts it.
double crater_field(const glm::dvec3& p, double cell, double depth_ratio, double density,
                    uint32_t seed) {
  double h = 0;
  craters::for_each_crater(p, cell, density, seed,
                           [&](const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t) {
                             double x = glm::length(q - c) / r;
                             if (x < craters::kReach) h += depth_ratio * r * cell * craters::profile(x);
                           });
  return h;
}

// The marks of the same craters on ground sampled every `spacing` metres.
void crater_marks_field(const glm::dvec3& p, double cell, double density, uint32_t seed,
                        double spacing, CraterMarks& marks) {
  craters::for_each_crater(p, cell, density, seed,
                           [&](const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t s) {
                             craters::add_marks(q, c, r, s, cell, spacing, marks);
                           });
}

}  // namespace

ProceduralHeight::ProceduralHeight(double radius, std::vector<NoiseLayer> layers, double offset,
                                   std::optional<double> sea_level)
    : radius_(radius), layers_(std::move(layers)), offset_(offset), sea_level_(sea_level) {
  double total = 0;
  for (const NoiseLayer& layer : layers_) {
    for_each_octave(layer, [&](int, double a, double freq) {
      // Craters: depth-to-radius ratio times the largest radius, a profile
      // spanning 1.0 of that, and overlapping craters.
      total += layer.kind == NoiseLayer::Kind::kCraters
                   ? kCraterOverlap * layer.amplitude / layer.wavelength * kCraterMaxRadius / freq
                   : a;
    });
  }
  raw_range_ = {offset_ - total, offset_ + total};
  range_ = raw_range_;
  if (sea_level_) range_.min = std::max(range_.min, *sea_level_);
}

void ProceduralHeight::set_land_mask(std::shared_ptr<const SurfaceMaps> maps) {
  if (maps && !sea_level_) throw std::logic_error("terrain: a land mask needs a sea level");
  maps_ = std::move(maps);
  range_ = maps_ ? shaped_range(raw_range_, 0.0, 1.0) : raw_range_;
  if (sea_level_) range_.min = std::max(range_.min, *sea_level_);
}

double ProceduralHeight::shaped(double h, double land) const {
  const double land_floor = *sea_level_ + kLandAbove, sea_ceiling = *sea_level_ - kSeaBelow;
  double up = h + soft_ramp(land_floor - h, kSoftening);
  double down = h - soft_ramp(h - sea_ceiling, kSoftening);
  // Settled land and sea take their bend alone, to the bit.
  double t = smoothstep(kLandEdge0, kLandEdge1, land);
  if (t == 1.0) return up;
  if (t == 0.0) return down;
  return down + t * (up - down);
}

HeightRange ProceduralHeight::shaped_range(HeightRange r, double land_min,
                                           double land_max) const {
  // shaped() grows with h (both bends do, and so their blend) and with
  // land (up is never below down).
  return {shaped(r.min, land_min), shaped(r.max, land_max)};
}

double ProceduralHeight::raw_height(const glm::dvec3& p) const {
  double h = offset_;
  for (const NoiseLayer& layer : layers_) {
    for_each_octave(layer, [&](int i, double a, double freq) {
      uint32_t seed = layer.seed * 131u + uint32_t(i);
      switch (layer.kind) {
        case NoiseLayer::Kind::kFbm: h += a * gradient_noise(p * freq, seed); break;
        case NoiseLayer::Kind::kRidged: {
          // Musgrave's ridged noise: 1 - |n| folds the zero crossings of
          // the noise into crests; |n| is rounded as sqrt(n^2 + e^2) - e so
          // that the crests stay C1 with bounded curvature (which the
          // interpolation error bound needs), then re-centred to about [-1, 1].
          double g = gradient_noise(p * freq, seed);
          double n = 1.0 - (std::sqrt(g * g + kRidgeRounding * kRidgeRounding) - kRidgeRounding);
          h += a * (2.0 * n * n - 1.0);
          break;
        }
        case NoiseLayer::Kind::kCraters:
          // amplitude / wavelength is the depth-to-radius ratio.
          h += crater_field(p, 1.0 / freq, layer.amplitude / layer.wavelength, layer.density,
                            seed);
          break;
      }
    });
  }
  return h;
}

double ProceduralHeight::seabed_height(const glm::dvec3& dir_body) const {
  double h = raw_height(dir_body * radius_);
  return maps_ ? shaped(h, maps_->land(dir_body)) : h;
}

double ProceduralHeight::height(const glm::dvec3& dir_body) const {
  double h = seabed_height(dir_body);
  return sea_level_ ? std::max(h, *sea_level_) : h;
}

CraterMarks ProceduralHeight::crater_marks(const glm::dvec3& dir_body, double spacing) const {
  CraterMarks marks;
  const glm::dvec3 p = dir_body * radius_;
  for (const NoiseLayer& layer : layers_) {
    if (layer.kind != NoiseLayer::Kind::kCraters) continue;
    for_each_octave(layer, [&](int i, double, double freq) {
      // Octaves whose widest craters cannot show are skipped.
      if (kCraterMaxRadius / freq < 1.5 * spacing) return;
      crater_marks_field(p, 1.0 / freq, layer.density, layer.seed * 131u + uint32_t(i), spacing,
                         marks);
    });
  }
  return marks;
}

HeightRange ProceduralHeight::range_near(const glm::dvec3& dir_body, double radius) const {
  // Each octave moves at most its slope bound times the distance, and
  // never more than its whole range.
  double spread = 0;
  for (const NoiseLayer& layer : layers_) {
    for_each_octave(layer, [&](int, double a, double freq) {
      switch (layer.kind) {
        case NoiseLayer::Kind::kFbm:
          spread += std::min(2.0 * a, a * kNoiseMaxSlope * freq * radius);
          break;
        case NoiseLayer::Kind::kRidged:
          spread += std::min(2.0 * a, 4.0 * a * kNoiseMaxSlope * freq * radius);
          break;
        case NoiseLayer::Kind::kCraters: {
          double ratio = layer.amplitude / layer.wavelength;
          spread += kCraterOverlap * std::min(kCraterMaxRadius * ratio / freq,
                                              ratio * kCraterMaxSlope * radius);
          break;
        }
      }
    });
  }
  double h = raw_height(dir_body * radius_);
  HeightRange r{std::max(h - spread, raw_range_.min), std::min(h + spread, raw_range_.max)};
  if (maps_) {
    // Far from any coast the mask is one value over the whole patch.
    bool one_value = maps_->distance_to_coast(dir_body) > radius;
    double land = one_value ? maps_->land(dir_body) : 0.0;
    r = shaped_range(r, land, one_value ? land : 1.0);
  }
  if (sea_level_) {
    r.min = std::max(r.min, *sea_level_);
    r.max = std::max(r.max, *sea_level_);
  }
  return r;
}

double ProceduralHeight::interpolation_error(double spacing) const {
  // Linear interpolation over a spacing h misses a function by at most
  // min(L h / 2, M h^2 / 8) for slope bound L and curvature bound M; the
  // error of a sum is at most the sum of the octaves' errors.
  double e = 0;
  for (const NoiseLayer& layer : layers_) {
    for_each_octave(layer, [&](int, double a, double freq) {
      switch (layer.kind) {
        case NoiseLayer::Kind::kFbm:
          e += std::min({2.0 * a, a * kNoiseMaxSlope * freq * spacing / 2.0,
                         a * kNoiseMaxCurvature * freq * freq * spacing * spacing / 8.0});
          break;
        case NoiseLayer::Kind::kRidged:
          e += std::min({2.0 * a, 4.0 * a * kNoiseMaxSlope * freq * spacing / 2.0,
                         a * kRidgedMaxCurvature * freq * freq * spacing * spacing / 8.0});
          break;
        case NoiseLayer::Kind::kCraters: {
          double ratio = layer.amplitude / layer.wavelength;
          double r_min = kCraterMinRadius / freq;
          e += kCraterOverlap * std::min({ratio * kCraterMaxSlope * spacing / 2.0,
                                          ratio / r_min * kCraterMaxCurvature * spacing * spacing / 8.0,
                                          kCraterMaxRadius * ratio / freq});
          break;
        }
      }
    });
  }
  if (maps_) e += land_mask_error(spacing);
  return e;
}

double ProceduralHeight::land_mask_error(double spacing) const {
  // shaped(h, land) = down(h) + t(land) (up(h) - down(h)). The bends have
  // slope at most 1 and curvature 1 / (2 k), which adds (dh)^2 / (16 k)
  // for a noise that changes by dh over the spacing; the blend adds the
  // gap G = up - down times t's own error, plus the cross term of t's and
  // the gap's changes over the spacing.
  double slope = 0;
  for (const NoiseLayer& layer : layers_) {
    for_each_octave(layer, [&](int, double a, double freq) {
      switch (layer.kind) {
        case NoiseLayer::Kind::kFbm: slope += a * kNoiseMaxSlope * freq; break;
        case NoiseLayer::Kind::kRidged: slope += 4.0 * a * kNoiseMaxSlope * freq; break;
        case NoiseLayer::Kind::kCraters:
          slope += kCraterOverlap * layer.amplitude / layer.wavelength * kCraterMaxSlope;
          break;
      }
    });
  }
  const double land_floor = *sea_level_ + kLandAbove, sea_ceiling = *sea_level_ - kSeaBelow;
  double dh = std::min(raw_range_.max - raw_range_.min, slope * spacing);
  double gap = std::max(land_floor + kSoftening - raw_range_.min, 0.0) +
               std::max(raw_range_.max - sea_ceiling + kSoftening, 0.0);
  double t_slope = 1.5 / (kLandEdge1 - kLandEdge0) * maps_->max_land_slope();
  double dt = std::min(1.0, t_slope * spacing);
  double bends = dh * dh / (16.0 * kSoftening);
  double blend = gap * dt / 2.0 + dt * dh / 4.0;
  return std::min(bends + blend, raw_range_.max - raw_range_.min + gap);
}

}  // namespace planet
