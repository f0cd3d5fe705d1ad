#include "lab/debiased_error.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace planet {

std::array<DebiasedError, 3> debiased_error(const ImageRGB& technique, const ImageRGB& reference,
                                            const ImageRGB& noise,
                                            const std::vector<uint8_t>& mask) {
  for (const ImageRGB* image : {&reference, &noise}) {
    if (image->width != technique.width || image->height != technique.height) {
      throw InputError(fmt::format("images of {}x{} and {}x{} cannot be compared",
                                   technique.width, technique.height, image->width,
                                   image->height));
    }
  }
  const size_t pixels = size_t(technique.width) * size_t(technique.height);
  std::array<DebiasedError, 3> out{};
  for (size_t c = 0; c < 3; ++c) {
    double squared = 0, noise_squared = 0, variance = 0, sum_reference = 0;
    size_t n = 0;
    for (size_t i = 0; i < pixels; ++i) {
      if (!mask.empty() && mask[i]) continue;
      double d = double(technique.pixels[i * 3 + c]) - double(reference.pixels[i * 3 + c]);
      double s2 = double(noise.pixels[i * 3 + c]) * double(noise.pixels[i * 3 + c]);
      squared += d * d;
      noise_squared += s2;
      // The pixel's own error squared, estimated (never below 0).
      double e2 = std::max(d * d - s2, 0.0);
      variance += 4.0 * e2 * s2 + 2.0 * s2 * s2;
      sum_reference += reference.pixels[i * 3 + c];
      ++n;
    }
    if (n == 0) continue;
    double count = double(n);
    double mse = (squared - noise_squared) / count;
    double half_width = 1.96 * std::sqrt(variance) / count;
    DebiasedError& e = out[c];
    e.rmse = std::sqrt(squared / count);
    e.debiased_rmse = std::sqrt(std::max(mse, 0.0));
    e.low = std::sqrt(std::max(mse - half_width, 0.0));
    e.high = std::sqrt(std::max(mse + half_width, 0.0));
    e.mean_reference = sum_reference / count;
  }
  return out;
}

}  // namespace planet
