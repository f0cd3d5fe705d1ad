// Spectrum -> linear sRGB against published facts about the CIE 1931
// observer and sRGB.
#include "atmosphere/spectrum.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::vector<double> every_nm(double step) {
  std::vector<double> w;
  for (double l = 380.0; l <= 780.0 + 1e-9; l += step) w.push_back(l);
  return w;
}

TEST(SpectrumTest, FlatSpectrumGivesEqualRgb) {
  auto w = every_nm(20.0);
  glm::dvec3 sum(0.0);
  for (const auto& v : srgb_weights(w)) sum += 2.5 * v;
  EXPECT_NEAR(sum.r, 2.5, 1e-12);
  EXPECT_NEAR(sum.g, 2.5, 1e-12);
  EXPECT_NEAR(sum.b, 2.5, 1e-12);
}

TEST(SpectrumTest, ObserverIntegralsMatchTheCieTable) {
  // The CIE 1931 functions each integrate to 106.86 nm over 360-830 nm
  // (equal-energy white has x = y = z = 1/3); over 380-780 nm sampled
  // every 5 nm the y integral is 106.85.
  glm::dvec3 integral(0.0);
  for (double l = 360.0; l <= 830.0; l += 1.0) integral += cie1931_xyz(l);
  EXPECT_NEAR(integral.x, 106.86, 0.02);
  EXPECT_NEAR(integral.y, 106.86, 0.02);
  EXPECT_NEAR(integral.z, 106.86, 0.05);
  EXPECT_NEAR(cie1931_xyz(555.0).y, 1.0, 1e-12);
}

TEST(SpectrumTest, D65WhiteOfSrgbIsNeutral) {
  // sRGB maps its white point, D65 (x, y) = (0.3127, 0.3290), to R = G = B.
  glm::dvec3 xyz(0.3127 / 0.3290, 1.0, (1.0 - 0.3127 - 0.3290) / 0.3290);
  glm::dvec3 rgb = linear_srgb_from_xyz(xyz);
  EXPECT_NEAR(rgb.r, 1.0, 2e-3);
  EXPECT_NEAR(rgb.g, 1.0, 2e-3);
  EXPECT_NEAR(rgb.b, 1.0, 2e-3);
}

TEST(SpectrumTest, MonochromaticLightHasItsHue) {
  auto w = every_nm(20.0);
  auto weights = srgb_weights(w);
  auto at = [&](double lambda) {
    for (size_t i = 0; i < w.size(); ++i) {
      if (w[i] == lambda) return weights[i];
    }
    return glm::dvec3(0.0);
  };
  glm::dvec3 red = at(660.0), green = at(540.0), blue = at(460.0);
  EXPECT_GT(red.r, 0.0);
  EXPECT_GT(red.r, red.g);
  EXPECT_GT(red.r, red.b);
  EXPECT_GT(green.g, green.r);
  EXPECT_GT(green.g, green.b);
  EXPECT_GT(blue.b, blue.r);
  EXPECT_GT(blue.b, blue.g);
}

TEST(SpectrumTest, WeightsConvergeWithSampling) {
  // A smooth spectrum (the sky's lambda^-4) gives nearly the same colour
  // from 21 samples as from 401: the sampling the body files use is enough.
  auto colour = [](double step) {
    auto w = every_nm(step);
    auto weights = srgb_weights(w);
    glm::dvec3 rgb(0.0);
    for (size_t i = 0; i < w.size(); ++i) rgb += std::pow(550.0 / w[i], 4.0) * weights[i];
    return rgb;
  };
  glm::dvec3 coarse = colour(20.0), fine = colour(1.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(coarse[c] / fine[c], 1.0, 5e-3) << c;
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
