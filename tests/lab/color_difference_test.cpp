// CIEDE2000 against the worked pairs of Sharma, Wu and Dalal 2005 (their
// table 1), and sRGB to CIELAB at white, black and a primary.
#include "lab/color_difference.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ColorDifferenceTest, Ciede2000MatchesSharmasPairs) {
  struct Pair {
    Lab one, two;
    double expected;
  };
  const Pair pairs[] = {
      {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
      {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
      {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
      {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
      {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0011}, 7.2195},
      {{2.0776, 0.0795, -1.135}, {0.9033, -0.0636, -0.5514}, 0.9082},
  };
  for (const Pair& p : pairs) {
    EXPECT_NEAR(ciede2000(p.one, p.two), p.expected, 1e-4);
    EXPECT_NEAR(ciede2000(p.two, p.one), p.expected, 1e-4);
  }
}

TEST(ColorDifferenceTest, SrgbToLabAtWhiteBlackAndRed) {
  Lab white = lab_from_srgb8(255, 255, 255), black = lab_from_srgb8(0, 0, 0);
  EXPECT_NEAR(white[0], 100.0, 0.01);
  EXPECT_NEAR(white[1], 0.0, 0.01);
  EXPECT_NEAR(white[2], 0.0, 0.01);
  EXPECT_NEAR(black[0], 0.0, 1e-9);
  Lab red = lab_from_srgb8(255, 0, 0);  // 53.24, 80.09, 67.20
  EXPECT_NEAR(red[0], 53.24, 0.05);
  EXPECT_NEAR(red[1], 80.09, 0.1);
  EXPECT_NEAR(red[2], 67.20, 0.1);
  std::vector<uint8_t> a = {255, 255, 255, 0, 0, 0}, b = {255, 255, 255, 255, 255, 255};
  EXPECT_NEAR(mean_ciede2000(a, b, {}), 50.0, 0.01);  // (0 + 100) / 2
  EXPECT_NEAR(mean_ciede2000(a, b, {0, 1}), 0.0, 1e-9);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
