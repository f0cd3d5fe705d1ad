#include "terrain/grid_detail.h"

#include "terrain/craters.h"
#include "terrain/noise.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

// The relief noise. In the grid's sample units (u, v), with the cells'
// edges at whole numbers after edge_offset, octave k (k = 1, 2, ...) of
// the detail is
//   d_k = (1 / m) [d/du (A_k F_k) + d/dv (A_k G_k)],  m = 2^k,
// where A_k is the octave's amplitude (smooth, from the nodes' local
// relief) and F_k, G_k are gradient noises on a lattice m times finer
// than the grid's (noise.h's edge_noise). F is zero all along the cells'
// vertical edges, G along their horizontal ones. Over a cell, the
// integral of d/du (A F) is that of A F along its east edge less that
// along its west edge (Gauss): zero, whatever A is; and so for
// d/dv (A G). The cell's mean is zero to the rounding, with no integral
// to compute. A sample is a lattice point (m is even) where neither noise
// has a gradient: both noises and their slopes are zero there, and so is
// d_k. Each octave is the divergence of a vector noise, so its spectrum
// is the noise's times |k|^2: the same in every direction.
double detail_fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double detail_fade_slope(double t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); }
constexpr double kFadeMaxSlope = 1.875;       // 30/16, at t = 1/2
constexpr double kFadeMaxCurvature = 5.7736;  // 10/sqrt(3), at t = (3 -+ sqrt 3) / 6

double detail_smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The fade toward the poles, by the cosine of the latitude: whole to 66
// degrees, none past 78, where a cell is under a fifth as wide as it is tall.
double polar_fade(double cos_latitude) { return detail_smoothstep(0.2, 0.4, cos_latitude); }

// How far a crater's influence on the sphere may reach past its drawn
// reach (its centre lies off the sphere; a cap's arc against its chord).
constexpr double kCraterReachMargin = 1.01;
// The zero-volume profile's deepest point, in units of its depth scale.
constexpr double kCraterMaxDepth = 1.733;

}  // namespace

GridDetail::GridDetail(std::shared_ptr<const GridData> data, double radius, double ellipsoid_ratio2,
                       std::optional<double> sea_level, const GridDetailSpec& spec)
    : GridHeight(std::move(data), radius, ellipsoid_ratio2, sea_level), spec_(spec) {
  const GridSpec& s = data_->spec();
  edge_offset_ = s.registration == GridSpec::Registration::kPixel ? 0.5 : 0.0;
  metres_per_row_ = radius_ / rows_per_radian();
  metres_per_column_ = radius_ * 2.0 * glm::pi<double>() / s.width;
  crater_cell_ = metres_per_row_;
  // The polar fade of a row's nodes over the cosine of any latitude
  // within a row of it: how much the detail's slopes grow as the columns
  // narrow toward the poles.
  const double row = 1.0 / rows_per_radian();
  for (int j = -1; j <= s.height; ++j) {
    double lat = std::abs(row_latitude(double(j)));
    double fade = polar_fade(std::cos(std::min(lat, 0.5 * glm::pi<double>())));
    if (fade == 0.0) continue;
    double cos_near = std::cos(std::min(lat + row, 0.5 * glm::pi<double>()));
    taper_over_cos_ = std::max(taper_over_cos_, fade / std::max(cos_near, 1e-9));
  }
  HeightRange all = seabed_range_near(glm::dvec3(0, 0, 1), 4.0 * radius_);
  double pad = relief_bound(spec_.max_amplitude_m, std::max(spec_.gain_smooth, spec_.gain_rough)) +
               crater_bound();
  detail_range_ = {all.min - pad, all.max + pad};
  if (sea_level_) {
    detail_range_.min = std::max(detail_range_.min, *sea_level_);
    detail_range_.max = std::max(detail_range_.max, *sea_level_);
  }
}

double GridDetail::amplitude_for(double relief) const {
  return std::clamp(spec_.relief_ratio * relief, spec_.min_amplitude_m, spec_.max_amplitude_m);
}

double GridDetail::gain_for(double relief) const {
  return spec_.gain_smooth + (spec_.gain_rough - spec_.gain_smooth) *
                                 detail_smoothstep(0.0, spec_.rough_relief_m, relief);
}

double GridDetail::relief_detail(double u, double v) const {
  const double fu = std::floor(u), fv = std::floor(v);
  const int i = int(fu), j = int(fv);
  double s[4][4];
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) s[b][a] = data_->sample(i - 1 + a, j - 1 + b);
  // The four nodes about (u, v): their first octave's amplitude and gain,
  // from the span of the 3 x 3 samples about each (within the 4 x 4 the
  // grid's interpolation reads).
  double amp[4], gain[4];
  bool any = false;
  for (int n = 0; n < 4; ++n) {
    const int a = n & 1, b = n >> 1;
    double lo = 1e300, hi = -1e300;
    for (int y = b; y < b + 3; ++y) {
      for (int x = a; x < a + 3; ++x) {
        lo = std::min(lo, s[y][x]);
        hi = std::max(hi, s[y][x]);
      }
    }
    const double relief = hi - lo;
    amp[n] = amplitude_for(relief) * polar_fade(std::cos(row_latitude(double(j + b))));
    if (sea_level_ && s[b + 1][a + 1] < *sea_level_) amp[n] *= spec_.sea_floor;
    gain[n] = gain_for(relief);
    any = any || amp[n] > 0.0;
  }
  if (!any) return 0.0;
  const double tu = u - fu, tv = v - fv;
  const double wu[2] = {1.0 - detail_fade(tu), detail_fade(tu)};
  const double wv[2] = {1.0 - detail_fade(tv), detail_fade(tv)};
  const double su = detail_fade_slope(tu), sv = detail_fade_slope(tv);
  const double dwu[2] = {-su, su}, dwv[2] = {-sv, sv};
  const int64_t width = data_->spec().width;
  double d = 0;
  for (int k = 1; k <= spec_.octaves; ++k) {
    const int64_t m = int64_t(1) << k;
    double A = 0, A_u = 0, A_v = 0;
    for (int n = 0; n < 4; ++n) {
      const int a = n & 1, b = n >> 1;
      A += wu[a] * wv[b] * amp[n];
      A_u += dwu[a] * wv[b] * amp[n];
      A_v += wu[a] * dwv[b] * amp[n];
      amp[n] *= gain[n];
    }
    // Lattice coordinates with the cells' edges at multiples of m; the
    // samples at m / 2 (pixel cells) or 0 (node cells) modulo m.
    const double x = double(m) * (u - edge_offset_), y = double(m) * (v - edge_offset_);
    const int64_t sample = edge_offset_ > 0.0 ? m / 2 : 0;
    const uint32_t seed = spec_.seed * 131u + 2u * uint32_t(k);
    EdgeNoise F, G;
    edge_noise_pair(x, y, m, sample, m * width, seed, seed + 1u, F, G);
    d += (A_u * F.value + A_v * G.value) / double(m) + A * (F.slope + G.slope);
  }
  return d;
}

bool GridDetail::crater_kept(const glm::dvec3& c, double r, double cell, uint32_t s) const {
  // The draw after the crater's youth and rays' phase (craters.h).
  craters::unit(s);
  craters::unit(s);
  const double draw = craters::unit(s);
  double uc, vc;
  grid_coordinates(glm::normalize(c), uc, vc);
  const double reach = kCraterReachMargin * craters::kReach * r * cell;
  const double lat = std::abs(row_latitude(vc));
  // The narrowest the columns get over the crater.
  const double cos_far = std::cos(std::min(lat + reach / radius_, 0.5 * glm::pi<double>()));
  if (draw >= polar_fade(cos_far)) return false;
  const double du = reach / (metres_per_column_ * cos_far), dv = reach / metres_per_row_;
  auto cell_of = [&](double x) { return std::floor(x - edge_offset_); };
  if (cell_of(uc - du) != cell_of(uc + du) || cell_of(vc - dv) != cell_of(vc + dv)) return false;
  // Off the cell's sample (a node grid's samples are the cells' corners,
  // which no kept crater reaches).
  if (edge_offset_ > 0.0) {
    const double east = (uc - std::round(uc)) * metres_per_column_ * cos_far;
    const double south = (vc - std::round(vc)) * metres_per_row_;
    if (east * east + south * south <= reach * reach) return false;
  }
  return true;
}

double GridDetail::crater_detail(const glm::dvec3& dir_body) const {
  if (spec_.crater_octaves <= 0) return 0.0;
  const glm::dvec3 p = dir_body * radius_;
  const double scale = spec_.crater_depth_ratio / craters::kZeroVolumeDepth;
  double h = 0, cell = crater_cell_;
  double density = spec_.crater_density;
  // Per octave, cells half as wide: the same chance gives N(>D) ~ D^-2;
  // each power of D beyond 2 doubles the chance per octave.
  const double density_step = std::pow(2.0, spec_.crater_sfd_exponent - 2.0);
  for (int o = 0; o < spec_.crater_octaves; ++o) {
    craters::for_each_surface_crater(
        p, cell, std::min(density, 1.0), spec_.crater_seed * 131u + uint32_t(o),
        [&](const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t s) {
          double x = glm::length(q - c) / r;
          if (x >= craters::kReach || !crater_kept(c, r, cell, s)) return;
          h += scale * r * cell * craters::zero_volume_profile(x);
        });
    cell *= 0.5;
    density *= density_step;
  }
  return h;
}

double GridDetail::detail(const glm::dvec3& dir_body) const {
  double u, v;
  grid_coordinates(dir_body, u, v);
  return relief_detail(u, v) + crater_detail(dir_body);
}

double GridDetail::seabed_height(const glm::dvec3& dir_body) const {
  const double grid = GridHeight::seabed_height(dir_body);
  double d = detail(dir_body);
  if (sea_level_) {
    // Coasts stay where the grid has them: near the sea's level the
    // detail moves the ground at most 0.9 of its height over (or under)
    // the sea.
    const double limit = 0.9 * std::abs(grid - *sea_level_);
    d = std::clamp(d, -limit, limit);
  }
  return grid + d;
}

double GridDetail::height(const glm::dvec3& dir_body) const {
  double h = seabed_height(dir_body);
  return sea_level_ ? std::max(h, *sea_level_) : h;
}

double GridDetail::relief_bound(double a0, double gain) const {
  // |d_k| <= (|A_u| |F| + |A_v| |G|) / m + |A| |F_x + G_y|, with A's slope
  // at most the fade's times the largest node amplitude.
  double bound = 0, a = a0;
  for (int k = 1; k <= spec_.octaves; ++k) {
    const double m = double(int64_t(1) << k);
    bound += a * (2.0 * kFadeMaxSlope * kEdgeNoiseMax / m + kEdgeDivergenceMax);
    a *= gain;
  }
  return bound;
}

double GridDetail::crater_bound() const {
  if (spec_.crater_octaves <= 0) return 0.0;
  const double scale = spec_.crater_depth_ratio / craters::kZeroVolumeDepth;
  // Each octave's craters at most kMaxRadius cells wide, overlapping.
  double bound = 0, cell = crater_cell_;
  for (int o = 0; o < spec_.crater_octaves; ++o, cell *= 0.5)
    bound += craters::kOverlap * scale * craters::kMaxRadius * cell * kCraterMaxDepth;
  return bound;
}

HeightRange GridDetail::range_near(const glm::dvec3& dir_body, double radius) const {
  // The nodes whose amplitudes reach the cap stand among the samples the
  // grid's own bound reads, so their relief is at most its span.
  HeightRange g = seabed_range_near(dir_body, radius);
  const double relief = g.max - g.min;
  const double gain = std::max(gain_for(0.0), gain_for(relief));
  const double pad = relief_bound(amplitude_for(relief), gain) + crater_bound();
  HeightRange r{std::max(g.min - pad, detail_range_.min), std::min(g.max + pad, detail_range_.max)};
  if (sea_level_) {
    r.min = std::max(r.min, *sea_level_);
    r.max = std::max(r.max, *sea_level_);
  }
  return r;
}

double GridDetail::interpolation_error(double spacing) const {
  // Each octave's chord misses it by at most half its slope bound times
  // the spacing, and never by more than twice its bound. In sample units,
  // |d d_k / du| <= a_k [(|A_uu| + |A_uv|) |F| / m + |A_u| (|F_x| + |G_x|
  // + |F_x + G_y|) + m |A| |d (F_x + G_y) / dx|], and so along v; in
  // metres, over columns narrowed by cos(latitude) (the polar fade bounds
  // the amplitude over it) and rows stretched by at most 1 % on a geodetic
  // grid, the two at right angles.
  const double grid = GridHeight::interpolation_error(spacing);
  const double per_metre =
      1.01 * std::hypot(taper_over_cos_ / metres_per_column_, 1.0 / metres_per_row_);
  const double gain = std::max(spec_.gain_smooth, spec_.gain_rough);
  double e = 0, a = spec_.max_amplitude_m;
  for (int k = 1; k <= spec_.octaves; ++k) {
    const double m = double(int64_t(1) << k);
    const double bound = a * (2.0 * kFadeMaxSlope * kEdgeNoiseMax / m + kEdgeDivergenceMax);
    const double slope = a * per_metre *
                         ((kFadeMaxCurvature + kFadeMaxSlope * kFadeMaxSlope) * kEdgeNoiseMax / m +
                          kFadeMaxSlope * (2.0 * kEdgeNoiseMaxSlope + kEdgeDivergenceMax) +
                          m * kEdgeDivergenceMaxSlope);
    e += std::min(2.0 * bound, 0.5 * slope * spacing);
    a *= gain;
  }
  if (spec_.crater_octaves > 0) {
    const double scale = spec_.crater_depth_ratio / craters::kZeroVolumeDepth;
    double cell = crater_cell_;
    for (int o = 0; o < spec_.crater_octaves; ++o, cell *= 0.5) {
      const double r_min = craters::kMinRadius * cell;
      e += craters::kOverlap *
           std::min({scale * craters::kMaxSlope * spacing / 2.0,
                     scale / r_min * craters::kMaxCurvature * spacing * spacing / 8.0,
                     2.0 * scale * craters::kMaxRadius * cell * kCraterMaxDepth});
    }
  }
  // The sea's limit on the detail follows the grid's height at 0.9 its slope.
  if (sea_level_)
    e += std::min(0.9 * grid, 2.0 * (relief_bound(spec_.max_amplitude_m, gain) + crater_bound()));
  return grid + e;
}

CraterMarks GridDetail::crater_marks(const glm::dvec3& dir_body, double spacing) const {
  CraterMarks marks;
  if (spec_.crater_octaves <= 0) return marks;
  const glm::dvec3 p = dir_body * radius_;
  double cell = crater_cell_, density = spec_.crater_density;
  const double density_step = std::pow(2.0, spec_.crater_sfd_exponent - 2.0);
  for (int o = 0; o < spec_.crater_octaves; ++o, cell *= 0.5, density *= density_step) {
    // Octaves whose widest craters cannot show are skipped.
    if (craters::kMaxRadius * cell < 1.5 * spacing) break;
    craters::for_each_surface_crater(
        p, cell, std::min(density, 1.0), spec_.crater_seed * 131u + uint32_t(o),
        [&](const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t s) {
          if (glm::length(q - c) >= craters::kReach * r) return;
          if (!crater_kept(c, r, cell, s)) return;
          craters::add_marks(q, c, r, s, cell, spacing, marks);
        });
  }
  return marks;
}

}  // namespace planet
