#include "sim/interpolation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace planet {

MonotoneCubic::MonotoneCubic(std::vector<double> t, std::vector<double> y)
    : t_(std::move(t)), y_(std::move(y)), m_(t_.size(), 0.0) {
  assert(!t_.empty() && t_.size() == y_.size());
  const size_t n = t_.size();
  if (n < 2) return;
  std::vector<double> delta(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) delta[i] = (y_[i + 1] - y_[i]) / (t_[i + 1] - t_[i]);
  m_[0] = delta[0];
  m_[n - 1] = delta[n - 2];
  for (size_t i = 1; i + 1 < n; ++i) {
    // Fritsch-Carlson: a weighted harmonic mean of the neighbouring slopes,
    // zero at a local extremum.
    if (delta[i - 1] * delta[i] <= 0.0) {
      m_[i] = 0.0;
    } else {
      double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
      double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
      m_[i] = (w0 + w1) / (w0 / delta[i - 1] + w1 / delta[i]);
    }
  }
  // The end slopes must not break monotonicity either.
  for (size_t end : {size_t{0}, n - 1}) {
    double d = delta[end == 0 ? 0 : n - 2];
    if (m_[end] * d <= 0.0) m_[end] = 0.0;
    else if (std::abs(m_[end]) > 3.0 * std::abs(d)) m_[end] = 3.0 * d;
  }
}

size_t MonotoneCubic::segment(double t) const {
  auto it = std::upper_bound(t_.begin(), t_.end(), t);
  size_t i = it == t_.begin() ? 0 : size_t(it - t_.begin()) - 1;
  return std::min(i, t_.size() - 2);
}

double MonotoneCubic::operator()(double t) const {
  if (t_.size() == 1 || t <= t_.front()) return y_.front();
  if (t >= t_.back()) return y_.back();
  size_t i = segment(t);
  double h = t_[i + 1] - t_[i];
  double s = (t - t_[i]) / h;
  double s2 = s * s, s3 = s2 * s;
  // Cubic Hermite basis.
  double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
  double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  return h00 * y_[i] + h10 * h * m_[i] + h01 * y_[i + 1] + h11 * h * m_[i + 1];
}

double MonotoneCubic::derivative(double t) const {
  if (t_.size() == 1 || t < t_.front() || t > t_.back()) return 0.0;
  size_t i = segment(t);
  double h = t_[i + 1] - t_[i];
  double s = (t - t_[i]) / h;
  double s2 = s * s;
  double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1;
  double d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  return (d00 * y_[i] + d01 * y_[i + 1]) / h + d10 * m_[i] + d11 * m_[i + 1];
}

}  // namespace planet
