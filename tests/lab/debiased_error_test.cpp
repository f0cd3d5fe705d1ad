// The debiased RMSE fed images with a known error and known noise: the
// plain RMSE carries the noise, the debiased one finds the error within its
// 95 % interval, over many noisy references about 95 % of the time.
#include "lab/debiased_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

struct Case {
  ImageRGB technique, reference, noise;
};

// A flat truth of 1; the technique off by `error` with alternating sign;
// the reference the truth plus Gaussian noise of standard error `sigma`.
Case make_case(double error, double sigma, std::mt19937_64& rng) {
  const int w = 64, h = 32;
  Case c;
  for (ImageRGB* image : {&c.technique, &c.reference, &c.noise}) {
    image->width = w;
    image->height = h;
    image->pixels.assign(size_t(w) * size_t(h) * 3, 0.0f);
  }
  std::normal_distribution<double> gauss(0.0, sigma);
  for (size_t i = 0; i < c.technique.pixels.size(); ++i) {
    c.technique.pixels[i] = float(1.0 + ((i / 3) % 2 ? error : -error));
    c.reference.pixels[i] = float(1.0 + gauss(rng));
    c.noise.pixels[i] = float(sigma);
  }
  return c;
}

TEST(DebiasedErrorTest, TakesTheNoiseOutAndItsIntervalHoldsTheTruth) {
  std::mt19937_64 rng(7);
  const double error = 0.02, sigma = 0.03;  // noise above the error itself
  int held = 0, trials = 200;
  double plain = 0, debiased = 0;
  for (int t = 0; t < trials; ++t) {
    Case c = make_case(error, sigma, rng);
    std::array<DebiasedError, 3> e = debiased_error(c.technique, c.reference, c.noise, {});
    plain += e[0].rmse / trials;
    debiased += e[0].debiased_rmse / trials;
    if (e[0].low <= error && error <= e[0].high) ++held;
  }
  // Plain: sqrt(error^2 + sigma^2) = 0.036; debiased: the error.
  EXPECT_NEAR(plain, std::sqrt(error * error + sigma * sigma), 0.001);
  EXPECT_NEAR(debiased, error, 0.001);
  EXPECT_GE(held, int(0.90 * trials));
  EXPECT_LE(held, trials);
}

// As the references have it (reference_render.cpp): the pixel the mean of
// two replicates, its noise estimated from their difference alone (one
// degree of freedom, so the estimate is itself as noisy as the noise).
TEST(DebiasedErrorTest, NoiseEstimatedFromTwoReplicatesStillHoldsTheTruth) {
  std::mt19937_64 rng(11);
  const double error = 0.02, sigma = 0.03;
  std::normal_distribution<double> gauss(0.0, sigma * std::sqrt(2.0));  // each replicate
  int held = 0, trials = 200;
  double debiased = 0;
  for (int t = 0; t < trials; ++t) {
    Case c = make_case(error, 0.0, rng);
    for (size_t i = 0; i < c.reference.pixels.size(); ++i) {
      double r0 = 1.0 + gauss(rng), r1 = 1.0 + gauss(rng);
      c.reference.pixels[i] = float(0.5 * (r0 + r1));
      c.noise.pixels[i] = float(0.5 * std::abs(r0 - r1));
    }
    std::array<DebiasedError, 3> e = debiased_error(c.technique, c.reference, c.noise, {});
    debiased += e[0].debiased_rmse / trials;
    if (e[0].low <= error && error <= e[0].high) ++held;
  }
  EXPECT_NEAR(debiased, error, 0.001);
  EXPECT_GE(held, int(0.90 * trials));
}

TEST(DebiasedErrorTest, NoNoiseIsThePlainRmseAndAMaskLeavesPixelsOut) {
  std::mt19937_64 rng(1);
  Case c = make_case(0.1, 0.0, rng);
  std::vector<uint8_t> mask(size_t(c.technique.width) * size_t(c.technique.height), 0);
  mask[0] = 1;
  c.technique.pixels[0] = 100.0f;  // masked out
  std::array<DebiasedError, 3> e = debiased_error(c.technique, c.reference, c.noise, mask);
  EXPECT_NEAR(e[1].rmse, 0.1, 1e-6);
  EXPECT_NEAR(e[1].debiased_rmse, 0.1, 1e-6);
  EXPECT_NEAR(e[1].low, 0.1, 1e-6);
  EXPECT_NEAR(e[1].high, 0.1, 1e-6);
  EXPECT_NEAR(e[1].relative(e[1].rmse), 0.1, 1e-6);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
