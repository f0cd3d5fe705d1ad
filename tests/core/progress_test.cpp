// A progress observer (what fly puts in its window's title while a
// technique's tables are computed) sees every update, quiet or shown, with
// the line a terminal would get and the fraction done. The time left of a
// job of unlike parts counts from their costs, not their number.
#include "core/progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ProgressTest, ObserverSeesQuietUpdatesWithTheirLineAndFraction) {
  std::vector<std::pair<std::string, double>> seen;
  set_progress_observer([&](const std::string& line, double fraction) {
    seen.emplace_back(line, fraction);
  });
  {
    Progress progress("bruneton tables (4 orders)", 4, "order", /*quiet=*/true);
    progress.update(1);
    progress.update(4);
  }
  set_progress_observer(nullptr);
  {
    Progress after("unobserved", 2, "order", true);
    after.update(2);
  }
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].first.rfind("bruneton tables (4 orders): order 1/4", 0), 0u) << seen[0].first;
  EXPECT_DOUBLE_EQ(seen[0].second, 0.25);
  EXPECT_DOUBLE_EQ(seen[1].second, 1.0);
}

// A sweep of two scenes whose first cell is cheap (1 s) and whose later
// ones are dear (50 s and 120 s): the parts' count alone says 5 s left
// after the first and 102 s after the second (the lab's "7 s, then 83 s");
// the costs say within a half of the truth throughout.
TEST(ProgressTest, CheapFirstPartThenDearOnesGiveNoTinyThenHugeTimeLeft) {
  const std::vector<ProgressPart> plan = {{"hillaire:cheap", 1},  {"bruneton", 40},
                                          {"bruneton:fine", 100}, {"hillaire:cheap", 1},
                                          {"bruneton", 40},       {"bruneton:fine", 100}};
  const std::vector<double> took = {1, 50, 120, 1, 50, 120};
  PartsEstimate estimate(plan);
  EXPECT_FALSE(estimate.seconds_left(0).has_value()) << "nothing is known before a part ends";
  double elapsed = 0, all = 0;
  for (double t : took) all += t;
  for (size_t k = 0; k + 1 < took.size(); ++k) {
    estimate.finished(k, took[k]);
    elapsed += took[k];
    double truth = all - elapsed;
    std::optional<double> left = estimate.seconds_left(k + 1);
    ASSERT_TRUE(left.has_value());
    EXPECT_GT(*left, truth / 1.5) << "after part " << k;
    EXPECT_LT(*left, truth * 1.5) << "after part " << k;
  }
  // The count alone, as the lab's line had it: a tiny time left, then a
  // large one (what the test guards against).
  auto by_count = [&](size_t done, double elapsed_then) {
    return elapsed_then / double(done) * double(took.size() - done);
  };
  EXPECT_LT(by_count(1, 1.0), (all - 1.0) / 10);
  EXPECT_GT(by_count(2, 51.0) / by_count(1, 1.0), 10);
}

// Parts kept from an earlier run (prior 0) cost nothing and teach nothing;
// the part under way counts what it has spent.
TEST(ProgressTest, KeptPartsTeachNothingAndThePartUnderWayCounts) {
  PartsEstimate estimate({{"a", 0}, {"a", 0}, {"a", 2}, {"b", 4}, {"a", 2}});
  estimate.finished(0, 0.01);
  estimate.finished(1, 0.01);
  EXPECT_FALSE(estimate.seconds_left(2).has_value());
  estimate.finished(2, 10);  // 5 s per unit of prior
  EXPECT_DOUBLE_EQ(*estimate.seconds_left(3), 20 + 10);
  EXPECT_DOUBLE_EQ(*estimate.seconds_left(3, 15), 5 + 10);
  EXPECT_DOUBLE_EQ(*estimate.seconds_left(3, 25), 0 + 10);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
