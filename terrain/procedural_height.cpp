#include "terrain/procedural_height.h"

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

// A ramp rounded over [-k, k]: 0 below, x above, a parabola between
// (slope in [0, 1], curvature 1 / (2 k)).
double soft_ramp(double x, double k) {
  if (x <= -k) return 0.0;
  if (x >= k) return x;
  return (x + k) * (x + k) / (4.0 * k);
}

// Where the map's land mask turns noise from sea to land.
constexpr double kLandEdge0 = 0.3, kLandEdge1 = 0.7;

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

// Calls f(q, c, r, s) for each crater that can reach p: q is p and c the
// crater's centre in cells of a lattice of spacing `cell`, r its radius
// in cells, s the state its cell's draws go on from. A cell holds a crater
// with chance `density`, its centre drawn within the cell in the order z,
// y, x, then its radius (each draw its own statement, so that every
// compiler places the same craters), between 0.1 and 0.25 cell: a crater
// reaches at most 0.625 cell from its centre, and only the neighbour cells
// on the near side of each axis can touch p.
template <typename F>
void for_each_crater(const glm::dvec3& p, double cell, double density, uint32_t seed, F&& f) {
  const glm::dvec3 q = p / cell;
  const glm::dvec3 floor = glm::floor(q);
  const glm::dvec3 frac = q - floor;
  auto lo = [](double t) { return t < kCraterMaxRadius * kCraterReach ? -1 : 0; };
  auto hi = [](double t) { return t > 1.0 - kCraterMaxRadius * kCraterReach ? 1 : 0; };
  auto cx = int64_t(floor.x), cy = int64_t(floor.y), cz = int64_t(floor.z);
  for (int dz = lo(frac.z); dz <= hi(frac.z); ++dz) {
    for (int dy = lo(frac.y); dy <= hi(frac.y); ++dy) {
      for (int dx = lo(frac.x); dx <= hi(frac.x); ++dx) {
        uint32_t s = cell_hash(cx + dx, cy + dy, cz + dz, seed);
        if (unit(s) >= density) continue;
        glm::dvec3 c;
        c.z = double(cz + dz) + unit(s);
        c.y = double(cy + dy) + unit(s);
        c.x = double(cx + dx) + unit(s);
        double r = kCraterMinRadius + (kCraterMaxRadius - kCraterMinRadius) * unit(s);
        f(q, c, r, s);
      }
    }
  }
}

// The craters' heights around p. Distances are taken in 3D: a centre off
// the surface gives a smaller, shallower crater where the sphere cuts it.
double crater_field(const glm::dvec3& p, double cell, double depth_ratio, double density,
                    uint32_t seed) {
  double h = 0;
  for_each_crater(p, cell, density, seed,
                  [&](const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t) {
                    double x = glm::length(q - c) / r;
                    if (x < kCraterReach) h += depth_ratio * r * cell * crater_profile(x);
                  });
  return h;
}

// The marks of the same craters on ground sampled every `spacing` metres.
// Each crater draws two more numbers after its radius: its youth y (most
// craters are old: y = u^3), and the phase of its rays. The floor covers
// the bowl; the rim a ring about 1.0-1.4 radii, bright on all but the
// oldest; the ejecta the blanket to 2.5 radii, on young craters alone,
// streaked by the sum of two cosines of the azimuth about the crater's
// centre (whole numbers of periods, so the streaks close on themselves).
// Marks of craters narrower than 1.5 `spacing` (the rim: 3) fade out;
// overlapping craters keep the strongest of each mark.
void crater_marks_field(const glm::dvec3& p, double cell, double density, uint32_t seed,
                        double spacing, CraterMarks& marks) {
  for_each_crater(
      p, cell, density, seed, [&](const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t s) {
        double youth = unit(s);
        youth = youth * youth * youth;
        double phase = 6.283185307179586 * unit(s);
        glm::dvec3 v = q - c;
        double x = glm::length(v) / r;
        if (x >= kCraterReach) return;
        double metres = r * cell;
        double shows = smoothstep(1.5 * spacing, 3.0 * spacing, metres);
        double rim_shows = smoothstep(3.0 * spacing, 6.0 * spacing, metres);
        marks.floor = std::max(marks.floor, shows * (1.0 - smoothstep(0.5, 0.9, x)));
        double ring = smoothstep(0.85, 1.05, x) * (1.0 - smoothstep(1.15, 1.45, x));
        marks.rim = std::max(marks.rim, rim_shows * (0.3 + 0.7 * youth) * ring);
        if (youth > 0.0 && x > 0.95) {
          // The azimuth in a frame about the centre's direction.
          glm::dvec3 n = glm::normalize(c);
          glm::dvec3 e1 = glm::normalize(
              glm::cross(n, std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
          glm::dvec3 e2 = glm::cross(n, e1);
          double azimuth = std::atan2(glm::dot(v, e2), glm::dot(v, e1));
          double streaks = 0.5 + 0.25 * std::cos(7.0 * azimuth + phase) +
                           0.25 * std::cos(12.0 * azimuth + 2.0 * phase);
          double blanket = smoothstep(0.95, 1.15, x) * (1.0 - smoothstep(1.2, kCraterReach, x));
          marks.ejecta =
              std::max(marks.ejecta, shows * youth * blanket * (0.3 + 0.7 * streaks * streaks));
        }
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
