// The frame's passes as a graph: ordered by what they read, skipped when
// not needed, reused while their inputs (and what they read) hold.
#include "gl/pass_graph.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace planet {
namespace {

// What the graph told: "run x", "reuse x", "skip x", in order.
class Log final : public PassRecorder {
 public:
  void begin(const std::string& pass) override { open_ = pass; }
  void end() override { lines.push_back("run " + open_); }
  void reuse(const std::string& pass) override { lines.push_back("reuse " + pass); }
  void skip(const std::string& pass) override { lines.push_back("skip " + pass); }
  std::vector<std::string> lines;

 private:
  std::string open_;
};

Pass pass(std::string name, std::vector<std::string> reads, int* input = nullptr,
          bool* needed = nullptr) {
  Pass p;
  p.name = std::move(name);
  p.reads = std::move(reads);
  if (input) p.inputs = [input] { return PassKey().add(*input); };
  if (needed) p.needed = [needed] { return *needed; };
  p.run = [] {};
  return p;
}

TEST(PassGraphTest, EachPassRunsAfterThePassesItReadsOtherwiseInTheOrderGiven) {
  Log log;
  PassGraph graph;
  graph.run({pass("sky", {"sky_view_lut", "transmittance_lut"}), pass("tonemap", {"sky"}),
             pass("sky_view_lut", {"transmittance_lut"}), pass("transmittance_lut", {})},
            log);
  EXPECT_EQ(log.lines, (std::vector<std::string>{"run transmittance_lut", "run sky_view_lut",
                                                 "run sky", "run tonemap"}));
}

TEST(PassGraphTest, APassWhoseInputsHoldIsReusedUntilTheyOrWhatItReadsChange) {
  int model = 1, sun = 10;
  PassGraph graph;
  auto frame = [&] {
    Log log;
    graph.run({pass("transmittance_lut", {}, &model), pass("sky_view_lut", {"transmittance_lut"}, &sun),
               pass("sky", {"sky_view_lut"})},
              log);
    return log.lines;
  };
  EXPECT_EQ(frame(), (std::vector<std::string>{"run transmittance_lut", "run sky_view_lut", "run sky"}));
  EXPECT_EQ(frame(), (std::vector<std::string>{"reuse transmittance_lut", "reuse sky_view_lut", "run sky"}));
  sun = 11;  // the view's own input
  EXPECT_EQ(frame(), (std::vector<std::string>{"reuse transmittance_lut", "run sky_view_lut", "run sky"}));
  model = 2;  // the table it reads is rebuilt: so is the view, its own inputs unchanged
  EXPECT_EQ(frame(), (std::vector<std::string>{"run transmittance_lut", "run sky_view_lut", "run sky"}));
  graph.forget();
  EXPECT_EQ(frame(), (std::vector<std::string>{"run transmittance_lut", "run sky_view_lut", "run sky"}));
  EXPECT_EQ(graph.runs("sky"), 1u);
}

TEST(PassGraphTest, APassTheFrameDoesNotNeedIsSkippedAndKeepsItsLastInputs) {
  int camera = 1;
  bool near_surface = true;
  PassGraph graph;
  auto frame = [&] {
    Log log;
    graph.run({pass("aerial_perspective", {}, &camera, &near_surface)}, log);
    return log.lines;
  };
  EXPECT_EQ(frame(), std::vector<std::string>{"run aerial_perspective"});
  near_surface = false;
  EXPECT_EQ(frame(), std::vector<std::string>{"skip aerial_perspective"});
  near_surface = true;
  EXPECT_EQ(frame(), std::vector<std::string>{"reuse aerial_perspective"});
}

TEST(PassGraphTest, APassThatTimesItselfIsNotTimedAroundButCounts) {
  Log log;
  PassGraph graph;
  Pass atmosphere = pass("atmosphere", {});
  atmosphere.times_itself = true;
  atmosphere.run = [&] { log.lines.push_back("its own passes"); };
  graph.run({std::move(atmosphere)}, log);
  EXPECT_EQ(log.lines, std::vector<std::string>{"its own passes"});
  EXPECT_EQ(graph.runs("atmosphere"), 1u);
}

TEST(PassGraphTest, ACycleAnUnknownReadOrATwiceNamedPassIsAnError) {
  Log log;
  PassGraph graph;
  EXPECT_THROW(graph.run({pass("a", {"b"}), pass("b", {"a"})}, log), std::logic_error);
  EXPECT_THROW(graph.run({pass("a", {"missing"})}, log), std::logic_error);
  EXPECT_THROW(graph.run({pass("a", {}), pass("a", {})}, log), std::logic_error);
  EXPECT_TRUE(log.lines.empty()) << "nothing runs before the order is known";
}

}  // namespace
}  // namespace planet
