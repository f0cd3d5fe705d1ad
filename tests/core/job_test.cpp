// The job engine's promises, each on a plan of a few cells in a temporary
// folder: results written whole, kept cells not run again (but with redo),
// shares that own every group once, the merge's "foreign", "twice" and
// "missing" shares, and progress that counts every cell.
#include "core/job.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::filesystem::path fresh_dir(const std::string& name) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("planet_job_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Two groups (scenes) of two cells (points) each.
std::vector<JobCell> plan() {
  return {{"cells/a/x.json", "a x", "a"},
          {"cells/a/y.json", "a y", "a"},
          {"cells/b/x.json", "b x", "b"},
          {"cells/b/y.json", "b y", "b"}};
}

// Runs the job, saying which cells ran and which groups were prepared.
struct Ran {
  std::vector<std::string> cells, prepared, kept;
};
Ran run(const Job& job, int fail_at = -1) {
  Ran ran;
  JobSteps steps;
  steps.prepare = [&](const JobCell& c) { ran.prepared.push_back(c.group); };
  steps.run = [&](const JobCell& c) {
    if (int(ran.cells.size()) == fail_at) throw std::runtime_error("killed");
    ran.cells.push_back(c.key);
    return "result of " + c.key + "\n";
  };
  steps.keep = [&](const JobCell& c, const std::filesystem::path& file) {
    ran.kept.push_back(c.key);
    return read(file) == "result of " + c.key + "\n";
  };
  job.run(steps);
  return ran;
}

TEST(JobTest, EachResultIsWrittenWholeUnderItsKey) {
  auto dir = fresh_dir("whole");
  Job job(dir, plan());
  Ran ran = run(job);
  EXPECT_EQ(ran.cells.size(), 4u);
  EXPECT_EQ(ran.prepared, (std::vector<std::string>{"a", "b"}));
  for (const JobCell& c : plan()) EXPECT_EQ(read(dir / c.key), "result of " + c.key + "\n");
  // No temporary neighbour is left beside a result.
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
  }
  std::filesystem::remove_all(dir);
}

TEST(JobTest, AJobStoppedPartWayGoesOnByKeyAndRunsNoKeptCellAgain) {
  auto dir = fresh_dir("resume");
  EXPECT_THROW(run(Job(dir, plan()), /*fail_at=*/2), std::runtime_error);
  EXPECT_TRUE(std::filesystem::exists(dir / "cells/a/y.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "cells/b/x.json"));
  // What a killed writer left looks like no result, and is cleared.
  std::filesystem::path stale = dir / "cells/a/.partial-999999999-z.json";
  std::ofstream(stale) << "half";
  Job again(dir, plan());
  EXPECT_EQ(again.left(), 2);
  Ran ran = run(again);
  EXPECT_EQ(ran.cells, (std::vector<std::string>{"cells/b/x.json", "cells/b/y.json"}));
  EXPECT_EQ(ran.kept, (std::vector<std::string>{"cells/a/x.json", "cells/a/y.json"}));
  EXPECT_EQ(ran.prepared, (std::vector<std::string>{"b"}));  // a's cells are all kept
  EXPECT_FALSE(std::filesystem::exists(stale));
  std::filesystem::remove_all(dir);
}

TEST(JobTest, AKeptResultThatIsNotWholeRunsAgain) {
  auto dir = fresh_dir("not_whole");
  run(Job(dir, plan()));
  std::ofstream(dir / "cells/b/x.json") << "{ not whole";
  Ran ran = run(Job(dir, plan()));
  EXPECT_EQ(ran.cells, (std::vector<std::string>{"cells/b/x.json"}));
  EXPECT_EQ(read(dir / "cells/b/x.json"), "result of cells/b/x.json\n");
  std::filesystem::remove_all(dir);
}

TEST(JobTest, RedoRunsEveryCellAgain) {
  auto dir = fresh_dir("redo");
  run(Job(dir, plan()));
  JobOptions redo;
  redo.redo = true;
  Job job(dir, plan(), redo);
  EXPECT_EQ(job.left(), 4);
  EXPECT_EQ(run(job).cells.size(), 4u);
  std::filesystem::remove_all(dir);
}

TEST(JobTest, SharesOwnEveryGroupOnceAndWholeWhateverTheSplit) {
  std::vector<JobCell> cells;
  for (int g = 0; g < 7; ++g) {
    for (int k = 0; k < 3; ++k) {
      cells.push_back({fmt::format("{}/{}", g, k), "", std::to_string(g)});
    }
  }
  for (ShareSplit split : {ShareSplit::kInterleaved, ShareSplit::kContiguous}) {
    for (int n : {1, 2, 3, 9}) {
      std::multiset<std::string> seen;
      for (int k = 0; k < n; ++k) {
        JobOptions o;
        o.share = {k, n};
        o.split = split;
        Job job("unused", cells, o);
        std::set<std::string> groups;
        for (const JobCell& c : job.cells()) seen.insert(c.key), groups.insert(c.group);
        EXPECT_EQ(job.cells().size(), 3 * groups.size());  // whole groups
        // The same share twice owns the same cells.
        EXPECT_EQ(Job("unused", cells, o).cells().size(), job.cells().size());
      }
      EXPECT_EQ(seen.size(), cells.size());
      for (const JobCell& c : cells) EXPECT_EQ(seen.count(c.key), 1u) << c.key;
    }
  }
  // Interleaved: group g to share g % N, as the stability map's shards.
  EXPECT_TRUE(share_owns({1, 3}, ShareSplit::kInterleaved, 4, 7));
  EXPECT_TRUE(share_owns({0, 2}, ShareSplit::kContiguous, 2, 7));
  EXPECT_FALSE(share_owns({0, 2}, ShareSplit::kContiguous, 3, 7));
}

TEST(JobTest, AKeyGivenTwiceIsRefused) {
  std::vector<JobCell> cells = plan();
  cells.push_back(cells.front());
  EXPECT_THROW(Job("unused", cells), InputError);
}

TEST(JobTest, ProgressCountsEveryCellAndTheTimeLeftLeavesKeptCellsOut) {
  auto dir = fresh_dir("progress");
  EXPECT_THROW(run(Job(dir, plan()), /*fail_at=*/1), std::runtime_error);
  Job job(dir, plan());
  std::vector<ProgressPart> parts = job.parts({{"x", 5}, {"y", 6}, {"x", 7}, {"y", 8}});
  EXPECT_EQ(parts[0].prior, 0);  // kept
  EXPECT_EQ(parts[1].prior, 6);
  EXPECT_EQ(parts[3].prior, 8);
  std::vector<std::string> lines;
  JobSteps steps;
  steps.run = [](const JobCell&) { return std::string("r"); };
  steps.progress = [&](int done, int total, const std::string& label) {
    lines.push_back(fmt::format("{}/{} {}", done, total, label));
  };
  job.run(steps);
  EXPECT_EQ(lines, (std::vector<std::string>{"0/4 a x", "1/4 a y", "2/4 b x", "3/4 b y", "4/4 "}));
  std::filesystem::remove_all(dir);
}

std::vector<ShareOf> shares_of(const std::vector<std::pair<int, std::string>>& shares, int count) {
  std::vector<ShareOf> out;
  for (const auto& [k, scene] : shares) {
    out.push_back({fmt::format("in/share-{}-of-{}", k, count),
                   {k, count},
                   {{"scene", scene}, {"share count", std::to_string(count)}}});
  }
  return out;
}

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(JobTest, AMergeNamesTheForeignShareTheOneGivenTwiceAndTheMissingOnes) {
  auto one = shares_of({{0, "noon"}, {1, "noon"}, {2, "sunset"}, {3, "noon"}}, 4);
  EXPECT_EQ(refusal([&] { require_one_job(one); }),
            "in/share-2-of-4: share 2/4 is of scene sunset, the other shares of noon");
  auto twice = shares_of({{0, "noon"}, {1, "noon"}, {1, "noon"}}, 2);
  EXPECT_EQ(refusal([&] { shares_by_index(twice, "noon", {"in"}); }),
            "share 1/2 is given twice: in/share-1-of-2 and in/share-1-of-2");
  auto missing = shares_of({{0, "noon"}, {2, "noon"}}, 4);
  EXPECT_EQ(refusal([&] { shares_by_index(missing, "noon", {"in"}); }),
            "shares 1/4, 3/4 of noon are missing from in (2 of 4 found)");
  auto whole = shares_of({{1, "noon"}, {0, "noon"}}, 2);
  require_one_job(whole);
  auto by_index = shares_by_index(whole, "noon", {"in"});
  ASSERT_EQ(by_index.size(), 2u);
  EXPECT_EQ(by_index[0]->share.index, 0);
  EXPECT_EQ(by_index[1]->share.index, 1);
}

TEST(JobTest, ACellThatDoesNotReadBackIsNamedWithTheWayOut) {
  auto dir = fresh_dir("read");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "half.json") << "{ \"a\": ";
  std::string half = refusal([&] { read_job_file(dir / "half.json", "planet lab run"); });
  EXPECT_EQ(half.rfind((dir / "half.json").string() + ": not a cell of planet lab run (", 0), 0u)
      << half;
  EXPECT_NE(half.find("); delete it or run with --redo"), std::string::npos) << half;
  auto read_a = [](const nlohmann::json& j) { return j.at("a").get<int>(); };
  EXPECT_EQ(read_job_json(nlohmann::json{{"a", 3}}, "x.json", "planet lab stability", read_a), 3);
  std::string wrong = refusal([&] {
    read_job_json(nlohmann::json{{"a", "three"}}, "x.json", "planet lab stability", read_a);
  });
  EXPECT_EQ(wrong.rfind("x.json: not a cell of planet lab stability (", 0), 0u) << wrong;
  std::filesystem::remove_all(dir);
}

// Ctrl-C while a job runs: at the next cell its command keeps what is done
// and says so, and the program ends as a shell reports SIGINT.
TEST(JobTest, CtrlCBetweenCellsKeepsWhatIsDoneAndSaysHowToGoOn) {
  // The exit runs the program's static destructors: in a fork of this
  // process, whose worker threads are not there, they would wait forever.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        JobProgress progress("job", "cell", "cells", /*quiet=*/true, "out/cells",
                             [] { std::fprintf(stderr, "folder kept\n"); });
        progress.update(0, 4);
        std::raise(SIGINT);
        progress.update(1, 4);
        std::exit(0);
      },
      ::testing::ExitedWithCode(kInterruptedExitStatus),
      "folder kept\nplanet: interrupted: 1 of 4 cells are done and kept in out/cells; run the "
      "same command again to go on");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
