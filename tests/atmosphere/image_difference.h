#pragma once
// How far one frame is from another, for the tests that draw a view two
// ways (pruned or not, reused or not, by either schedule).
#include <algorithm>
#include <cmath>
#include <vector>

namespace planet {

// The largest difference of a value of a from b's, over the larger of the
// two: 0 for the same bits, about 6e-8 for a float's last bit.
inline double largest_relative_difference(const std::vector<float>& a,
                                          const std::vector<float>& b) {
  if (a.size() != b.size()) return INFINITY;
  double worst = 0.0;
  for (size_t i = 0; i < b.size(); ++i) {
    double scale = std::max(std::abs(double(a[i])), std::abs(double(b[i])));
    if (scale > 0.0) worst = std::max(worst, std::abs(double(a[i]) - double(b[i])) / scale);
  }
  return worst;
}

// The largest over R, G and B of the RMSE of a against b over the mean of
// b: the lab's relative RMSE, without its noise terms (neither is noisy).
// `lit_only`: over the pixels with light in b alone, for a planet that
// fills a few pixels of a black frame (the whole frame's would weigh its
// differences by the frame's size over the planet's).
inline double relative_rmse(const std::vector<float>& a, const std::vector<float>& b,
                            bool lit_only = false) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double sum_sq = 0.0, sum = 0.0;
    size_t n = 0;
    for (size_t i = size_t(c); i < b.size(); i += 4) {
      const size_t pixel = i - size_t(c);
      if (lit_only && b[pixel] == 0.0f && b[pixel + 1] == 0.0f && b[pixel + 2] == 0.0f) continue;
      double d = double(a[i]) - double(b[i]);
      sum_sq += d * d;
      sum += b[i];
      ++n;
    }
    double mean = sum / double(n);
    if (mean > 0.0) worst = std::max(worst, std::sqrt(sum_sq / double(n)) / mean);
  }
  return worst;
}

}  // namespace planet
