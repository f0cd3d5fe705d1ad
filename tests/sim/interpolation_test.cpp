#include "sim/interpolation.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(MonotoneCubicTest, PassesThroughKeysWithContinuousSlope) {
  MonotoneCubic f({0, 1, 3, 4}, {0, 10, 11, 40});
  EXPECT_DOUBLE_EQ(f(0), 0);
  EXPECT_DOUBLE_EQ(f(1), 10);
  EXPECT_DOUBLE_EQ(f(3), 11);
  EXPECT_DOUBLE_EQ(f(4), 40);
  for (double t : {1.0, 3.0}) {
    EXPECT_NEAR(f.derivative(t - 1e-9), f.derivative(t + 1e-9), 1e-6);
    EXPECT_NEAR(f(t - 1e-6), f(t + 1e-6), 1e-3);
  }
}

TEST(MonotoneCubicTest, NoOvershootBetweenMonotoneKeys) {
  // A climb from 2 m to 400 km: a plain cubic spline dips below the start.
  MonotoneCubic f({0, 10, 20, 40}, {2, 3000, 30000, 400000});
  double previous = f(0);
  for (double t = 0; t <= 40; t += 0.01) {
    double v = f(t);
    EXPECT_GE(v, previous - 1e-9) << t;
    EXPECT_GE(v, 2.0 - 1e-9);
    previous = v;
  }
}

TEST(MonotoneCubicTest, FlatAtLocalExtremum) {
  MonotoneCubic f({0, 1, 2}, {0, 5, 0});
  EXPECT_NEAR(f.derivative(1.0), 0.0, 1e-12);
  for (double t = 0; t <= 2; t += 0.01) EXPECT_LE(f(t), 5.0 + 1e-12);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
