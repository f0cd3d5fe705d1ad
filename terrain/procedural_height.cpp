#include "terrain/procedural_height.h"

#include "terrain/noise.h"

#include <algorithm>
#include <cmath>

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

// A simple crater, depth D and radius R, as a function of x = d / R: a
// parabolic bowl whose floor lies D below the plain, and a rim 0.3 D high
// that falls back to the plain by x = 2.5 (the simple-crater shape of
// Melosh 1989, ch. 6). Bowl and rim meet through a polynomial smooth
// minimum (Quilez 2013) of width 0.2, which keeps the profile C1 with
// bounded curvature, so that its interpolation error is bounded as h^2.
double crater_profile(double x) {
  double bowl = x * x - 0.7;
  double rim = 0.3 * (1.0 - smoothstep(1.0, 2.5, x));
  constexpr double k = 0.2;
  double m = std::clamp(0.5 + 0.5 * (rim - bowl) / k, 0.0, 1.0);
  return rim + (bowl - rim) * m - k * m * (1.0 - m);
}
// Its slope and curvature bounds in units of D / R and D / R^2: the bowl's
// slope 2x up to where the minimum hands over (x ~ 1.2), and its curvature
// 2 plus the blend's (bowl' - rim')^2 / (2 k).
constexpr double kCraterMaxSlope = 3.0;
constexpr double kCraterMaxCurvature = 20.0;
constexpr double kCraterReach = 2.5;  // profile is zero beyond this many radii
// Crater radii in cells, and how many craters can overlap at a point (one
// per cell of the 2 x 2 x 2 block that can reach it).
constexpr double kCraterMinRadius = 0.1, kCraterMaxRadius = 0.25;
constexpr double kCraterOverlap = 8.0;

// Rounding of the ridged crests, in units of the noise's range, and the
// curvature bound that follows: with r = 1 - (sqrt(g^2 + e^2) - e),
// |r''| <= (2 S^2 / e + C) f^2 and |(2 r^2)''| <= 4 (S^2 f^2 + |r''|).
constexpr double kRidgeRounding = 0.1;
constexpr double kRidgedMaxCurvature =
    4.0 * (kNoiseMaxSlope * kNoiseMaxSlope +
           2.0 * kNoiseMaxSlope * kNoiseMaxSlope / kRidgeRounding + kNoiseMaxCurvature);

uint32_t cell_hash(int64_t x, int64_t y, int64_t z, uint32_t seed) {
  uint64_t h = uint64_t(x) * 0xD6E8FEB86659FD93ull ^ uint64_t(y) * 0xA0761D6478BD642Full ^
               uint64_t(z) * 0xE7037ED1A0B428DBull ^ uint64_t(seed) * 0x8EBC6AF09C88C6E3ull;
  h ^= h >> 32;
  h *= 0x9E3779B97F4A7C15ull;
  h ^= h >> 29;
  return uint32_t(h);
}
double unit(uint32_t& state) {
  state = state * 1664525u + 1013904223u;  // Numerical Recipes LCG, enough for placement
  return double(state >> 8) / double(1u << 24);
}

// Craters whose centres lie in the cells of a lattice of spacing `cell`
// around p, radii between 0.1 and 0.25 cell, so that a crater reaches at
// most 0.625 cell from its centre and only the neighbour cells on the near
// side of each axis can touch p. Distances are taken in 3D: a centre off
// the surface gives a smaller, shallower crater where the sphere cuts it.
double crater_field(const glm::dvec3& p, double cell, double depth_ratio, double density,
                    uint32_t seed) {
  glm::dvec3 q = p / cell;
  glm::dvec3 f = glm::floor(q);
  glm::dvec3 frac = q - f;
  auto lo = [](double t) { return t < kCraterMaxRadius * kCraterReach ? -1 : 0; };
  auto hi = [](double t) { return t > 1.0 - kCraterMaxRadius * kCraterReach ? 1 : 0; };
  auto cx = int64_t(f.x), cy = int64_t(f.y), cz = int64_t(f.z);
  double h = 0;
  for (int dz = lo(frac.z); dz <= hi(frac.z); ++dz) {
    for (int dy = lo(frac.y); dy <= hi(frac.y); ++dy) {
      for (int dx = lo(frac.x); dx <= hi(frac.x); ++dx) {
        uint32_t s = cell_hash(cx + dx, cy + dy, cz + dz, seed);
        if (unit(s) >= density) continue;
        glm::dvec3 c(double(cx + dx) + unit(s), double(cy + dy) + unit(s),
                     double(cz + dz) + unit(s));
        double r = kCraterMinRadius + (kCraterMaxRadius - kCraterMinRadius) * unit(s);
        double x = glm::length(q - c) / r;
        if (x < kCraterReach) h += depth_ratio * r * cell * crater_profile(x);
      }
    }
  }
  return h;
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
  range_ = {offset_ - total, offset_ + total};
  if (sea_level_) range_.min = std::max(range_.min, *sea_level_);
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

double ProceduralHeight::height(const glm::dvec3& dir_body) const {
  double h = raw_height(dir_body * radius_);
  return sea_level_ ? std::max(h, *sea_level_) : h;
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
  HeightRange r{std::max(h - spread, range_.min), std::min(h + spread, range_.max)};
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
  return e;
}

}  // namespace planet
