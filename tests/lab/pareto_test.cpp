// The Pareto front on synthetic tables: dominated points off, ties on,
// equal cost or equal error resolved by the other count.
#include "lab/pareto.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ParetoTest, KeepsTheUndominatedAndTies) {
  std::vector<CostError> points = {
      {1.0, 0.50},  // cheapest: on
      {2.0, 0.20},  // on
      {2.0, 0.30},  // same cost, worse error: off
      {3.0, 0.20},  // same error, dearer: off
      {4.0, 0.05},  // on
      {4.0, 0.05},  // a tie with the one before: both on
      {5.0, 0.40},  // dominated by (2, 0.2): off
      {9.0, 0.01},  // dearest, best: on
  };
  std::vector<bool> expected = {true, true, false, false, true, true, false, true};
  EXPECT_EQ(pareto_front(points), expected);
}

TEST(ParetoTest, OnePointAndNoneAreTheirOwnFront) {
  EXPECT_EQ(pareto_front({{3.0, 0.1}}), std::vector<bool>{true});
  EXPECT_TRUE(pareto_front({}).empty());
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
