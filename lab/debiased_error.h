#pragma once
// The RMSE of a technique against a noisy reference, with the reference's
// noise taken out. Each reference pixel is the truth plus noise of known
// standard error s (its replicates give it): the squared difference d^2 of a
// pixel has expectation e^2 + s^2, e the technique's own error. The sum of
// d^2 - s^2 over the pixels is then an unbiased estimate of the sum of e^2,
// with variance sum (4 e^2 s^2 + 2 s^4) for Gaussian noise, from which a
// 95 % interval follows. A reference whose noise is comparable to the error
// (rather than a tenth of it) then serves. The references estimate s from
// two replicates (reference_render.cpp): s^2 stays unbiased, and the
// variance of its estimate (2 s^4 more) is covered, as the estimate's
// square averages 3 s^4 (a test holds the interval so).
#include "core/image_io.h"

#include <array>
#include <cstdint>
#include <vector>

namespace planet {

struct DebiasedError {
  double rmse = 0;           // plain, noise included
  double debiased_rmse = 0;  // noise taken out (0 where the noise explains it all)
  double low = 0, high = 0;  // 95 % interval of the debiased RMSE
  double mean_reference = 0;
  double relative(double v) const { return mean_reference > 0 ? v / mean_reference : 0.0; }
};

// Per channel over the pixels with mask 0 (empty mask: all of them);
// `noise` is the reference's standard error per pixel and channel.
std::array<DebiasedError, 3> debiased_error(const ImageRGB& technique, const ImageRGB& reference,
                                            const ImageRGB& noise,
                                            const std::vector<uint8_t>& mask);

}  // namespace planet
