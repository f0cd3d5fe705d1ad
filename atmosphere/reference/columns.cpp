#include "atmosphere/reference/columns.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

namespace planet {

namespace {

// The table holds log(column + kLogOffset): a column falls exponentially
// with altitude, so its logarithm interpolates linearly almost exactly
// (30x closer than the columns themselves at the same size, measured). The
// offset (1 mm) keeps the log finite where a column vanishes, at the top.
constexpr double kLogOffset = 1e-3;

// Six-point Gauss-Legendre on [-1, 1] (Abramowitz and Stegun 25.4.30).
constexpr std::array<double, 3> kNodes = {0.2386191860831969, 0.6612093864662645,
                                          0.9324695142031521};
constexpr std::array<double, 3> kWeights = {0.4679139345726910, 0.3607615730481386,
                                            0.1713244923791704};

glm::dvec3 densities(const Medium& m, double altitude) {
  return {density_at(m.rayleigh_density, altitude), density_at(m.mie_density, altitude),
          density_at(m.absorber_density, altitude)};
}

// Where a profile's derivative jumps: the boundary between its layers, and
// where a linear layer or an exponential one is clamped to 0 or 1.
void add_breaks(const DensityProfile& p, std::vector<double>& breaks) {
  breaks.push_back(p.layers[0].width);
  for (const DensityLayer& l : p.layers) {
    if (l.exp_term == 0.0 && l.linear_term != 0.0) {
      breaks.push_back(-l.constant_term / l.linear_term);
      breaks.push_back((1.0 - l.constant_term) / l.linear_term);
    }
    if (l.exp_term > 1.0 && l.exp_scale != 0.0 && l.linear_term == 0.0 && l.constant_term == 0.0) {
      breaks.push_back(-std::log(l.exp_term) / l.exp_scale);
    }
  }
}

// The least scale height of the exponential layers: the rule's pieces
// span at most a few of them in altitude.
double least_scale_height(const Medium& m) {
  double least = 10e3;
  for (const DensityProfile* p : {&m.rayleigh_density, &m.mie_density, &m.absorber_density}) {
    for (const DensityLayer& l : p->layers) {
      if (l.exp_term != 0.0 && l.exp_scale != 0.0)
        least = std::min(least, 1.0 / std::abs(l.exp_scale));
    }
  }
  return least;
}

}  // namespace

ColumnTable::ColumnTable(const Medium& medium, int r_size, int mu_size)
    : medium_(medium), r_size_(r_size), mu_size_(mu_size) {
  const double bottom = medium.bottom_radius, top = medium.top_radius;
  horizon_ = std::sqrt(top * top - bottom * bottom);
  for (const DensityProfile* p :
       {&medium.rayleigh_density, &medium.mie_density, &medium.absorber_density}) {
    add_breaks(*p, breaks_);
  }
  std::erase_if(breaks_, [&](double h) { return !(h > 0.0 && h < top - bottom); });
  std::sort(breaks_.begin(), breaks_.end());
  step_ = 4.0 * least_scale_height(medium);

  texels_.resize(size_t(r_size) * size_t(mu_size));
  auto fill_rows = [&](int first, int step) {
    for (int i = first; i < r_size; i += step) {
      double rho = horizon_ * i / (r_size - 1);
      double r = std::sqrt(rho * rho + bottom * bottom);
      double d_min = top - r, d_max = rho + horizon_;
      for (int j = 0; j < mu_size; ++j) {
        double d = d_min + (d_max - d_min) * j / (mu_size - 1);
        double mu = d == 0.0 ? 1.0 : (horizon_ * horizon_ - rho * rho - d * d) / (2.0 * r * d);
        texels_[size_t(i) * size_t(mu_size) + size_t(j)] =
            glm::log(integrate_to_top(r, std::clamp(mu, -1.0, 1.0)) + kLogOffset);
      }
    }
  };
  int threads = std::max(1, int(std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(fill_rows, t, threads);
  for (auto& t : pool) t.join();
}

glm::dvec3 ColumnTable::integrate_to_top(double r, double mu) const {
  const double bottom = medium_.bottom_radius, top = medium_.top_radius;
  r = std::clamp(r, bottom, top);
  double rho = std::sqrt(std::max(r * r - bottom * bottom, 0.0));
  mu = std::clamp(mu, -rho / r, 1.0);  // at most down to the horizon
  // In s = sqrt(r' - r_p), with r' the distance from the centre along the
  // ray and r_p its least value, dt = 2 r' / sqrt(2 r_p + s^2) ds.
  // A rising ray never reaches its tangent point; a falling one passes it
  // above the ground.
  double r_p = r * std::sqrt(std::max(1.0 - mu * mu, 0.0));
  if (mu < 0.0) r_p = std::max(r_p, bottom);
  auto altitude_to_s = [&](double h) { return std::sqrt(std::max(bottom + h - r_p, 0.0)); };
  // Integral from the point at altitude h0 up to altitude h1 along the
  // ray's rising part, over pieces of at most step_ in altitude and
  // broken at every kink.
  auto rising = [&](double h0, double h1) {
    glm::dvec3 sum(0.0);
    double lo = h0;
    auto next_break = std::upper_bound(breaks_.begin(), breaks_.end(), h0);
    while (lo < h1) {
      double hi = std::min(lo + step_, h1);
      if (next_break != breaks_.end() && *next_break < hi) hi = *next_break++;
      double s0 = altitude_to_s(lo), s1 = altitude_to_s(hi);
      double half = 0.5 * (s1 - s0), mid = 0.5 * (s1 + s0);
      for (size_t k = 0; k < kNodes.size(); ++k) {
        for (double sign : {-1.0, 1.0}) {
          double s = mid + sign * half * kNodes[k];
          double rr = r_p + s * s;
          sum += kWeights[k] * half * 2.0 * rr / std::sqrt(2.0 * r_p + s * s) *
                 densities(medium_, rr - bottom);
        }
      }
      lo = hi;
    }
    return sum;
  };
  double h_here = r - bottom, h_top = top - bottom, h_tangent = r_p - bottom;
  if (mu >= 0.0) return rising(h_here, h_top);
  // Down to the tangent point, then up from it to the top.
  return rising(h_tangent, h_here) + rising(h_tangent, h_top);
}

ColumnTable::Cell ColumnTable::locate(double r, double mu) const {
  const double bottom = medium_.bottom_radius, top = medium_.top_radius;
  r = std::clamp(r, bottom, top);
  double rho = std::sqrt(std::max(r * r - bottom * bottom, 0.0));
  mu = std::clamp(mu, -rho / r, 1.0);
  double d = std::max(-r * mu + std::sqrt(std::max(r * r * (mu * mu - 1.0) + top * top, 0.0)), 0.0);
  double d_min = top - r, d_max = rho + horizon_;
  double x_r = rho / horizon_;
  double x_mu = d_max > d_min ? (d - d_min) / (d_max - d_min) : 0.0;
  double u = std::clamp(x_r, 0.0, 1.0) * (r_size_ - 1);
  double v = std::clamp(x_mu, 0.0, 1.0) * (mu_size_ - 1);
  int i = std::min(int(u), r_size_ - 2), j = std::min(int(v), mu_size_ - 2);
  return {i, j, u - i, v - j};
}

glm::dvec3 ColumnTable::texel(int i, int j) const {
  return glm::exp(texels_[size_t(i) * size_t(mu_size_) + size_t(j)]) - kLogOffset;
}

glm::dvec3 ColumnTable::to_top(double r, double mu) const {
  Cell c = locate(r, mu);
  auto at = [&](int a, int b) { return texels_[size_t(a) * size_t(mu_size_) + size_t(b)]; };
  return glm::exp((1.0 - c.fu) * ((1.0 - c.fv) * at(c.i, c.j) + c.fv * at(c.i, c.j + 1)) +
                  c.fu * ((1.0 - c.fv) * at(c.i + 1, c.j) + c.fv * at(c.i + 1, c.j + 1))) -
         kLogOffset;
}

glm::dvec3 ColumnTable::to_top(const glm::dvec3& p, const glm::dvec3& dir) const {
  double r = glm::length(p);
  return to_top(r, glm::dot(p, dir) / r);
}

namespace {
// The depth table's offset under its logarithms, in optical depth: where a
// depth is below it (near the top) the interpolation is linear in depth,
// and a transmittance error there is below 1e-7.
constexpr double kDepthOffset = 1e-7;
}  // namespace

DepthTable::DepthTable(const ColumnTable& columns, const MediumChannel& channel)
    : columns_(columns), channel_(channel) {
  const size_t mu_size = size_t(columns.mu_size());
  texels_.resize(size_t(columns.r_size()) * mu_size);
  for (int i = 0; i < columns.r_size(); ++i) {
    for (int j = 0; j < columns.mu_size(); ++j) {
      glm::dvec3 column = columns.texel(i, j);
      texels_[size_t(i) * mu_size + size_t(j)] = {
          float(std::log(channel.rayleigh_scattering * column.x + kDepthOffset)),
          float(std::log((channel.mie_scattering + channel.mie_absorption) * column.y +
                         kDepthOffset)),
          float(channel.absorber_absorption * column.z)};
    }
  }
}

double DepthTable::to_top(double r, double mu) const {
  ColumnTable::Cell c = columns_.locate(r, mu);
  const size_t mu_size = size_t(columns_.mu_size());
  const glm::vec3* row = texels_.data() + size_t(c.i) * mu_size + size_t(c.j);
  const glm::vec3* next = row + mu_size;
  glm::dvec3 mixed =
      (1.0 - c.fu) * ((1.0 - c.fv) * glm::dvec3(row[0]) + c.fv * glm::dvec3(row[1])) +
      c.fu * ((1.0 - c.fv) * glm::dvec3(next[0]) + c.fv * glm::dvec3(next[1]));
  return std::max(std::exp(mixed.x) - kDepthOffset, 0.0) +
         std::max(std::exp(mixed.y) - kDepthOffset, 0.0) + mixed.z;
}

}  // namespace planet
