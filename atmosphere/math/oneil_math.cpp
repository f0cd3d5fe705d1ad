// O'Neil 2005's functions in their one C++ translation unit (see
// oneil_math.h), and the fit of the scale function.
#include "atmosphere/math/oneil_math.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace planet::oneil {

using namespace glm;
using namespace shared;
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
// The CPU's skies have no Moon (oneil_functions.glsl's includer's).
Real3 eclipse_sun_share(IN(Real3), IN(Real3)) { return Real3(1.0); }
// clang-format off
#include "atmosphere/shaders/oneil_functions.glsl"
// clang-format on
#undef IN
#undef OUT
#undef INOUT

namespace {

// Simpson intervals along a ray for exact_column, with the samples crowded
// toward the start (t = L u^2), where the air is densest. From 600 to 200
// no body's worst fit error moved in its fourth digit, at a third of the
// time (a body's two fits and errors: 0.3 s).
constexpr int kExactIntervals = 200;

// The grid of the fit and of its error, over y = h / thickness and x = 1 - mu.
constexpr int kFitHeights = 41, kFitCosines = 81;
constexpr int kErrorHeights = 101, kErrorCosines = 241;
// Reweighting rounds toward the worst residual (Lawson's algorithm).
constexpr int kReweightRounds = 30;

// Zenith cosine k of n from the horizon of radius r (a ray that grazes the
// ground, nudged off it) to straight up, denser toward the horizon, where
// the column changes fastest.
double cosine_at(const Atmosphere& a, double r, int k, int n) {
  double mu_horizon =
      -std::sqrt(std::max(1.0 - (a.bottom_radius / r) * (a.bottom_radius / r), 0.0));
  double s = double(k) / double(n - 1);
  double mu = mu_horizon + (1.0 - mu_horizon) * s * s;
  return std::min(mu + 1e-9 * (1.0 - mu_horizon), 1.0);
}

// Least squares min |A c - b| (rows of `cols` values) by Householder QR.
std::vector<double> least_squares(std::vector<double> A, std::vector<double> b, int cols) {
  const int rows = int(b.size());
  for (int k = 0; k < cols; ++k) {
    double norm = 0;
    for (int i = k; i < rows; ++i) norm += A[size_t(i * cols + k)] * A[size_t(i * cols + k)];
    norm = std::sqrt(norm);
    if (norm == 0) continue;
    double alpha = A[size_t(k * cols + k)] > 0 ? -norm : norm;
    std::vector<double> v(size_t(rows - k));
    for (int i = k; i < rows; ++i) v[size_t(i - k)] = A[size_t(i * cols + k)];
    v[0] -= alpha;
    double vv = 0;
    for (double e : v) vv += e * e;
    if (vv == 0) continue;
    auto reflect = [&](auto at) {
      double dot = 0;
      for (int i = k; i < rows; ++i) dot += v[size_t(i - k)] * at(i);
      double f = 2.0 * dot / vv;
      for (int i = k; i < rows; ++i) at(i) -= f * v[size_t(i - k)];
    };
    for (int j = k; j < cols; ++j) {
      reflect([&](int i) -> double& { return A[size_t(i * cols + j)]; });
    }
    reflect([&](int i) -> double& { return b[size_t(i)]; });
  }
  std::vector<double> c(size_t(cols), 0.0);
  for (int k = cols - 1; k >= 0; --k) {
    double s = b[size_t(k)];
    for (int j = k + 1; j < cols; ++j) s -= A[size_t(k * cols + j)] * c[size_t(j)];
    double d = A[size_t(k * cols + k)];
    c[size_t(k)] = d != 0 ? s / d : 0.0;
  }
  return c;
}

}  // namespace

Real exact_column(const Atmosphere& atmosphere, Real scale_height, Real r, Real mu) {
  Real length = distance_to_top_boundary(atmosphere, r, mu);
  auto density = [&](double u) {
    double t = length * u * u;
    double r_t = std::sqrt(t * t + 2.0 * r * mu * t + r * r);
    // dt = 2 L u du
    return std::exp(-(std::max(r_t - atmosphere.bottom_radius, 0.0)) / scale_height) * 2.0 * u;
  };
  double sum = density(0.0) + density(1.0);
  for (int i = 1; i < kExactIntervals; ++i) {
    sum += (i % 2 == 1 ? 4.0 : 2.0) * density(double(i) / kExactIntervals);
  }
  return length * sum / (3.0 * kExactIntervals);
}

ScaleError measure_scale_error(const Atmosphere& atmosphere, const OneilScale& scale) {
  ScaleError e;
  const double thickness = atmosphere.top_radius - atmosphere.bottom_radius;
  const double H = scale.scale_height;
  const double vertical = H * -std::expm1(-thickness / H);
  for (int i = 0; i < kErrorHeights; ++i) {
    double h = thickness * double(i) / double(kErrorHeights - 1);
    double r = atmosphere.bottom_radius + h;
    for (int k = 0; k < kErrorCosines; ++k) {
      double mu = cosine_at(atmosphere, r, k, kErrorCosines);
      double exact = exact_column(atmosphere, H, r, mu);
      double approx = oneil_column(atmosphere, scale, r, mu);
      double absolute = std::abs(approx - exact);
      e.worst_of_vertical = std::max(e.worst_of_vertical, absolute / vertical);
      // Upward from the very top the column is 0 in both forms.
      if (exact <= 1e-12 * vertical) continue;
      double relative = absolute / exact;
      if (relative > e.worst_relative) {
        e.worst_relative = relative;
        e.worst_h = h;
        e.worst_mu = mu;
      }
    }
  }
  return e;
}

OneilScale chapter_scale(Real scale_height) {
  OneilScale s{};
  s.scale_height = scale_height;
  s.kind = kOneilChapter;
  return s;
}

// The fit: the upward column's logarithm less that of its closed-form part
// V G is Q(x, y), linear in the coefficients. Downward rays are not fitted:
// they are made of upward ones. Plain least squares leaves its worst error
// at the horizon; Lawson's reweighting (each point's weight times its
// residual, renormalised) moves toward the minimax fit.
OneilScale fit_scale(const Atmosphere& atmosphere, Real scale_height) {
  OneilScale s{};
  s.scale_height = scale_height;
  s.kind = kOneilFitted;
  const double thickness = atmosphere.top_radius - atmosphere.bottom_radius;
  std::vector<double> rows, targets;
  for (int i = 0; i < kFitHeights; ++i) {
    // Up to just below the top, where the column and V vanish together.
    double y = 0.999 * double(i) / double(kFitHeights - 1);
    double r = atmosphere.bottom_radius + y * thickness;
    for (int k = 0; k < kFitCosines; ++k) {
      double v = double(k) / double(kFitCosines - 1);
      double mu = v * v;  // denser toward the horizon
      double exact = exact_column(atmosphere, scale_height, r, mu);
      OneilScale zero = s;  // Q = 0: the closed-form part alone
      double closed = oneil_column_up(atmosphere, zero, r, mu);
      if (!(exact > 0) || !(closed > 0)) continue;
      double left = thickness * (1.0 - y);
      double depth = scale_height * left / (scale_height + left);
      double x = oneil_horizon_variable(r, depth, mu);
      double z = oneil_height_variable(scale_height, thickness, depth);
      for (int a = 0; a < kOneilXTerms; ++a) {
        for (int b = 0; b < kOneilYTerms; ++b) {
          rows.push_back(std::pow(x, a + 1) * std::pow(z, b));
        }
      }
      targets.push_back(std::log(exact / closed));
    }
  }
  const size_t n = targets.size();
  std::vector<double> weights(n, 1.0), c;
  for (int round = 0; round < kReweightRounds; ++round) {
    std::vector<double> A(rows.size()), b(n);
    for (size_t p = 0; p < n; ++p) {
      double w = std::sqrt(weights[p]);
      for (int q = 0; q < kOneilTerms; ++q) {
        A[p * kOneilTerms + size_t(q)] = w * rows[p * kOneilTerms + size_t(q)];
      }
      b[p] = w * targets[p];
    }
    c = least_squares(std::move(A), std::move(b), kOneilTerms);
    double total = 0;
    for (size_t p = 0; p < n; ++p) {
      double fit = 0;
      for (int q = 0; q < kOneilTerms; ++q) fit += rows[p * kOneilTerms + size_t(q)] * c[size_t(q)];
      weights[p] *= std::abs(fit - targets[p]) + 1e-12;
      total += weights[p];
    }
    for (double& w : weights) w *= double(n) / total;
  }
  for (int q = 0; q < kOneilTerms; ++q) s.c[q] = c[size_t(q)];
  return s;
}

Real exponential_scale_height(const shared::DensityProfile& profile, const std::string& component) {
  const shared::DensityLayer& l = profile.layers[1];
  bool one_exponential = profile.layers[0].width == 0 && l.exp_term == 1.0 && l.exp_scale < 0 &&
                         l.linear_term == 0 && l.constant_term == 0;
  if (!one_exponential) {
    throw InputError(fmt::format(
        "oneil: the {} density is not one exponential layer, which the scale function needs",
        component));
  }
  return -1.0 / l.exp_scale;
}

BodyScales fit_body_scales(const AtmosphereModel& model) {
  Atmosphere a = to_shared(model);
  BodyScales out;
  Real h_rayleigh = exponential_scale_height(model.rayleigh.density, "Rayleigh");
  Real h_mie = exponential_scale_height(model.mie.density, "Mie");
  out.rayleigh = fit_scale(a, h_rayleigh);
  out.mie = fit_scale(a, h_mie);
  out.rayleigh_error = measure_scale_error(a, out.rayleigh);
  out.mie_error = measure_scale_error(a, out.mie);
  return out;
}

}  // namespace planet::oneil
