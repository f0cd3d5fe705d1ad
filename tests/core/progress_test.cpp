// A progress observer (what fly puts in its window's title while a
// technique's tables are computed) sees every update, quiet or shown, with
// the line a terminal would get and the fraction done.
#include "core/progress.h"

#include <gtest/gtest.h>

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

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
