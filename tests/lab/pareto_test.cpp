// The Pareto front on synthetic tables: dominated points off, ties on,
// equal cost or equal error resolved by the other count; costs within
// their measured spreads (centred on them) and errors within their
// intervals tie.
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

// A sweep's two quality points whose frames' times spread over 8 and 10
// ms, 2.8 ms apart, with errors inside each other's intervals: neither is
// cheaper or more accurate beyond the noise, so both are on the front and
// each ties with the other in time.
TEST(ParetoTest, PointsWithinTheirNoiseTieAndBothStay) {
  CostError fine{27.9, 0.0082, 8.0, 0.0080, 0.0085};
  CostError standard{30.7, 0.0084, 10.0, 0.0081, 0.0087};
  CostError cheap{12.0, 0.0300, 1.0, 0.0290, 0.0310};
  EXPECT_TRUE(costs_tie(fine, standard));
  EXPECT_TRUE(errors_tie(fine, standard));
  EXPECT_FALSE(costs_tie(fine, cheap));
  EXPECT_EQ(pareto_front({fine, standard, cheap}), (std::vector<bool>{true, true, true}));
  std::vector<std::vector<size_t>> ties = cost_ties({fine, standard, cheap});
  EXPECT_EQ(ties[0], std::vector<size_t>{1});
  EXPECT_EQ(ties[1], std::vector<size_t>{0});
  EXPECT_TRUE(ties[2].empty());
}

// Beyond the noise the front is as before: a point as cheap within its
// spread but less accurate beyond the intervals is off, and so is one as
// accurate but dearer by more than the spreads reach.
TEST(ParetoTest, BeyondTheNoiseTheBetterPointWins) {
  CostError a{27.9, 0.0082, 8.0, 0.0080, 0.0085};
  CostError worse{30.7, 0.0120, 10.0, 0.0110, 0.0130};  // ties in time, clearly worse
  CostError dearer{60.0, 0.0083, 5.0, 0.0081, 0.0086};  // ties in error, clearly dearer
  EXPECT_EQ(pareto_front({a, worse, dearer}), (std::vector<bool>{true, false, false}));
  // Without spreads or intervals the counts are exact, as they were.
  EXPECT_EQ(pareto_front({{27.9, 0.0082}, {30.7, 0.0084}}), (std::vector<bool>{true, false}));
}

TEST(ParetoTest, OnePointAndNoneAreTheirOwnFront) {
  EXPECT_EQ(pareto_front({{3.0, 0.1}}), std::vector<bool>{true});
  EXPECT_TRUE(pareto_front({}).empty());
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
