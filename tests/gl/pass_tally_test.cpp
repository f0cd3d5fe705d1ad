// The passes of many frames, summed as fly prints them when it closes.
#include "gl/pass_tally.h"

#include <gtest/gtest.h>

namespace planet {
namespace {

PassTiming ran(const std::string& pass, double gpu_ms) { return {pass, gpu_ms, 0.0, false, false}; }
PassTiming reused(const std::string& pass) { return {pass, 0.0, 0.0, true, false}; }

TEST(PassTallyTest, MeansOverTheFramesEachPassRanCostliestFirst) {
  PassTally tally;
  tally.add({ran("sky_view_lut", 20.0), ran("sky", 30.0), ran("surface", 10.0)});
  tally.add({reused("sky_view_lut"), ran("sky", 50.0), ran("surface", 14.0)});
  tally.add({reused("sky_view_lut"), ran("sky", 40.0), ran("surface", 12.0)});
  EXPECT_EQ(tally.frames(), 3);
  const PassTally::Pass& view = tally.passes().at("sky_view_lut");
  EXPECT_EQ(view.ran, 1);
  EXPECT_EQ(view.reused, 2);
  EXPECT_DOUBLE_EQ(view.gpu_ms, 20.0);
  // sky 40 ms a frame, then the view's 20 (over the one frame it ran, not
  // three), then the surfaces' 12.
  EXPECT_EQ(tally.summary(),
            "  sky              40.00 ms  ran 3 of 3\n"
            "  sky_view_lut     20.00 ms  ran 1 of 3, reused 2\n"
            "  surface          12.00 ms  ran 3 of 3\n");
}

TEST(PassTallyTest, WallTimeWhereTheTimerWasSynchronous) {
  PassTally tally;
  tally.add({{"sky", 1e-6, 80.0, false, false}});
  tally.add({{"sky", 1e-6, 100.0, false, false}});
  EXPECT_EQ(tally.summary(), "  sky     90.00 ms  ran 2 of 2\n");
}

TEST(PassTallyTest, CountsTheFramesThatSkippedAPass) {
  PassTiming skipped{"aerial_perspective"};
  skipped.skipped = true;
  PassTally tally;
  tally.add({ran("aerial_perspective", 6.0), ran("sky", 10.0)});
  tally.add({skipped, ran("sky", 10.0)});
  EXPECT_EQ(tally.summary(),
            "  sky" + std::string(20, ' ') + "10.00 ms  ran 2 of 2\n"
            "  aerial_perspective      6.00 ms  ran 1 of 2, skipped 1\n");
}

TEST(PassTallyTest, NoFramesNoLines) {
  EXPECT_EQ(PassTally().summary(), "");
  EXPECT_EQ(PassTally().table(), "");
}

// --pass-table: wall and GPU time side by side (on llvmpipe the queries
// miss what runs in the calling thread), the counts in columns, the frame
// as a whole last.
TEST(PassTallyTest, TableGivesWallAndGpuTimeAndTheCounts) {
  PassTiming skipped{"stars"};
  skipped.skipped = true;
  PassTally tally;
  tally.add({{"surface", 10.0, 40.0, false, false}, reused("sky_view_lut"), skipped});
  tally.add(
      {{"surface", 14.0, 60.0, false, false}, {"sky_view_lut", 2.0, 8.0, false, false}, skipped});
  EXPECT_EQ(tally.table(),
            "  pass             wall ms      GPU ms    ran  reused  skipped\n"
            "  surface            50.00       12.00      2       0        0\n"
            "  sky_view_lut        8.00        2.00      1       1        0\n"
            "  stars               0.00        0.00      0       0        2\n"
            "  frame              54.00       13.00      2\n");
}

TEST(PassTallyTest, TableMarksWallTimesNotKept) {
  PassTally tally;
  tally.add({ran("sky", 10.0)});
  EXPECT_EQ(tally.table(),
            "  pass      wall ms      GPU ms    ran  reused  skipped\n"
            "  sky             -       10.00      1       0        0\n"
            "  frame           -       10.00      1\n");
}

}  // namespace
}  // namespace planet
