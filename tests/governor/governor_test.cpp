// The governor's choice from its table, without GL: the cheapest choice
// within budget at the lab's own views, hysteresis that keeps it from
// flapping, a fade on every switch, and tables and scripts that are wrong
// refused with their file and field named.
#include "governor/governor.h"

#include "core/error.h"
#include "lab/scene.h"
#include "sim/flight_script.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

ViewFeatures view(double altitude_m, double sun_deg, std::string body = "earth") {
  ViewFeatures v;
  v.body = std::move(body);
  v.altitude_m = altitude_m;
  v.shell_m = 100e3;
  v.sun_elevation_deg = sun_deg;
  v.optical_depth = 0.2;
  v.mie_g = 0.8;
  v.bottom_radius_m = 6360e3;
  return v;
}

// Two views of Earth: the ground at noon, where "fast" is good enough, and
// orbit, where only "slow" is.
ErrorModel two_views() {
  ErrorModel m;
  m.source = "test";
  m.time_width = 640;
  m.time_height = 360;
  m.model_change_ms = {{"fast", 1000.0}, {"slow", 0.0}, {"exact", 100000.0}};
  ViewClass ground{"ground", view(2, 60), {{"fast", 0.02, 0.025, 10}, {"slow", 0.01, 0.012, 30},
                                          {"exact", 0.001, 0.002, 60}}};
  ViewClass orbit{"orbit", view(400e3, 60), {{"fast", 0.20, 0.25, 10}, {"slow", 0.03, 0.035, 30},
                                             {"exact", 0.002, 0.003, 50}}};
  m.classes = {ground, orbit};
  return m;
}

GovernorSettings per_frame(double budget) {
  GovernorSettings s;
  s.budget_percent = budget;
  s.frames_per_model = 0;
  return s;
}

TEST(GovernorTest, AtTheLabsOwnViewsTheChoiceIsTheCheapestWithinBudget) {
  for (double budget : {0.5, 1.5, 2.5, 5.0, 50.0}) {
    for (const ViewFeatures& v : {view(2, 60), view(400e3, 60)}) {
      Governor g(two_views(), per_frame(budget), "hillaire");
      GovernorDecision d = g.decide(v);
      ASSERT_TRUE(d.governed);
      // The table's answer, by hand.
      const ErrorModel table = two_views();
      const ViewClass& c = table.classes[v.altitude_m > 1e3 ? 1 : 0];
      std::string cheapest, accurate;
      double cost = 1e300, error = 1e300;
      for (const ErrorModelEntry& e : c.entries) {
        if (e.error <= budget / 100 && e.frame_ms < cost) cost = e.frame_ms, cheapest = e.choice;
        if (e.error < error) error = e.error, accurate = e.choice;
      }
      std::string expected = cheapest.empty() ? accurate : cheapest;
      EXPECT_EQ(d.choice, expected) << "budget " << budget << " % at " << c.scene;
      EXPECT_EQ(d.within_budget, !cheapest.empty());
      EXPECT_EQ(d.classes, std::vector<std::string>{c.scene});
      EXPECT_EQ(d.most_accurate.choice, accurate);
      EXPECT_NE(d.why.find(d.choice), std::string::npos) << d.why;
    }
  }
}

TEST(GovernorTest, AModelChangeSpreadOverTheFramesCountsInTheCost) {
  // Per frame "fast" (10 ms) wins at 5 %; with its 1 s of tables spread
  // over 20 frames it costs 60 ms, and "exact" 5020 ms: "slow" (30 ms) wins.
  GovernorSettings s = per_frame(5.0);
  EXPECT_EQ(Governor(two_views(), s, "x").decide(view(2, 60)).choice, "fast");
  s.frames_per_model = 20;
  GovernorDecision d = Governor(two_views(), s, "x").decide(view(2, 60));
  EXPECT_EQ(d.choice, "slow");
  EXPECT_DOUBLE_EQ(d.chosen.cost_ms, 30.0);
}

TEST(GovernorTest, BetweenTwoViewsThePredictionIsTheWorseOfThem) {
  ErrorModel m = two_views();
  m.classes[1].view = view(150e3, 60);  // orbit just over a class away from the ground
  Governor g(m, per_frame(5.0), "x");
  std::vector<std::string> classes;
  double distance = 0;
  // Halfway between them: both rows, each choice at the worse.
  ViewFeatures between = view(2, 60);
  between.altitude_m = 58e3;
  auto p = g.predict(between, &classes, &distance);
  EXPECT_EQ(classes.size(), 2u);
  EXPECT_GT(distance, 0.0);
  for (const Prediction& x : p) {
    if (x.choice == "fast") {
      EXPECT_DOUBLE_EQ(x.error, 0.20);
    }
    if (x.choice == "slow") {
      EXPECT_DOUBLE_EQ(x.error, 0.03);
    }
  }
}

TEST(GovernorTest, ABodyTheTableDoesNotHaveDrawsTheFallback) {
  Governor g(two_views(), per_frame(5.0), "hillaire");
  GovernorDecision d = g.decide(view(2, 60, "vulcan"));
  EXPECT_FALSE(d.governed);
  EXPECT_EQ(d.choice, "hillaire");
  EXPECT_NE(d.why.find("vulcan"), std::string::npos) << d.why;
}

TEST(GovernorTest, HysteresisHoldsACheaperChoiceForItsDwellAndLeavesAnOverBudgetOneAtOnce) {
  GovernorSettings s = per_frame(4.0);
  s.dwell_frames = 5;
  s.fade_frames = 4;
  Governor g(two_views(), s, "x");
  // Orbit first: "slow" (3 %) within 4 %.
  EXPECT_EQ(g.decide(view(400e3, 60)).choice, "slow");
  // Down to the ground: "fast" is a third of the cost, taken after 5 frames.
  for (int i = 1; i < 5; ++i) {
    GovernorDecision d = g.decide(view(2, 60));
    EXPECT_EQ(d.choice, "slow") << "frame " << i;
    EXPECT_EQ(d.cheapest.choice, "fast");
  }
  GovernorDecision switched = g.decide(view(2, 60));
  EXPECT_EQ(switched.choice, "fast");
  // The switch's frame is the old one's; it fades out over the next frames.
  EXPECT_EQ(switched.fading_from, "slow");
  EXPECT_DOUBLE_EQ(switched.fade_weight, 1.0);
  double last = 1.0;
  int fading = 0;
  for (int i = 0; i < 6; ++i) {
    GovernorDecision d = g.decide(view(2, 60));
    if (d.fading_from.empty()) break;
    EXPECT_LT(d.fade_weight, last);
    last = d.fade_weight;
    ++fading;
  }
  EXPECT_EQ(fading, s.fade_frames - 1);
  // Back up: "fast" is 20 % there, over budget, left on the first frame.
  GovernorDecision up = g.decide(view(400e3, 60));
  EXPECT_EQ(up.choice, "slow");
  EXPECT_EQ(up.fading_from, "fast");
}

TEST(GovernorTest, AViewThatWavesAcrossTwoClassesDoesNotFlap) {
  GovernorSettings s = per_frame(25.0);  // both within budget in both views
  Governor g(two_views(), s, "x");
  int switches = 0;
  std::string last;
  for (int i = 0; i < 200; ++i) {
    // Every third frame in orbit: "fast" is within 25 % and the cheapest
    // in both views, so nothing moves.
    GovernorDecision d = g.decide(i % 3 ? view(2, 60) : view(400e3, 60));
    if (!last.empty() && d.choice != last) ++switches;
    last = d.choice;
  }
  EXPECT_EQ(switches, 0);
  // Where the cheapest alternates with the view, the dwell holds the choice.
  ErrorModel m = two_views();
  m.classes[1].entries[0].frame_ms = 40;  // fast costs more than slow in orbit
  Governor h(m, s, "x");
  switches = 0;
  last.clear();
  for (int i = 0; i < 200; ++i) {
    GovernorDecision d = h.decide(i % 4 < 2 ? view(2, 60) : view(400e3, 60));
    if (!last.empty() && d.choice != last) ++switches;
    last = d.choice;
  }
  EXPECT_EQ(switches, 0) << "a choice alternating every two frames must not be followed";
}

class GovernorFileTest : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::filesystem::path file = dir_ / name;
    std::ofstream(file) << text;
    return file;
  }
  void SetUp() override {
    // One folder per process and test: ctest runs this fixture's tests in
    // processes side by side, and gtest's random seed (the folder's name
    // before) came from the clock's milliseconds, the same in both; one
    // test's TearDown then removed the folder the other was writing.
    dir_ = std::filesystem::temp_directory_path() /
           ("governor_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

std::string error_of(const std::filesystem::path& file) {
  try {
    load_error_model(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(GovernorFileTest, ABadTableIsRefusedWithItsFileAndField) {
  nlohmann::json good = error_model_to_json(two_views());
  auto file = write("good.json", good.dump());
  EXPECT_EQ(error_of(file), "");
  EXPECT_EQ(load_error_model(file).classes.size(), 2u);

  auto expect = [&](const std::string& name, const std::string& text, const std::string& says) {
    std::string e = error_of(write(name, text));
    EXPECT_NE(e.find(name), std::string::npos) << e;
    EXPECT_NE(e.find(says), std::string::npos) << name << ": " << e;
  };
  expect("empty.json", "", "not JSON");
  expect("array.json", "[1, 2]", "not an error model");
  nlohmann::json j = good;
  j["format"] = "something-else";
  expect("format.json", j.dump(), "format");
  j = good;
  j["classes"][0]["entries"][1]["choice"] = "fast";
  expect("twice.json", j.dump(), "listed twice");
  j = good;
  j["classes"][1]["view"]["mie_g"] = 3.0;
  expect("g.json", j.dump(), "mie_g");
  j = good;
  j["classes"][0]["entries"][0].erase("frame_ms");
  expect("missing.json", j.dump(), "frame_ms");
  j = good;
  j["classes"][0]["extra"] = 1;
  expect("extra.json", j.dump(), "extra");
  EXPECT_NE(error_of(dir_).find("no error model"), std::string::npos) << error_of(dir_);
  EXPECT_NE(error_of(dir_ / "none.json").find("none.json"), std::string::npos);
}

TEST_F(GovernorFileTest, AScriptGivesABudgetOrATechniqueNotBoth) {
  std::string base = R"({"body": "earth", "image": {"width": 64, "height": 32}, "frame_rate": 1,
    "sun": {"elevation_deg": 20, "azimuth_deg": 90},
    "keyframes": [{"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 1000},
                  {"time": 1, "lat_deg": 0, "lon_deg": 0, "height_m": 2000}])";
  FlightScript s = load_flight_script(write("budget.json", base + R"(, "error_budget_pct": 5})"));
  ASSERT_TRUE(s.error_budget_percent.has_value());
  EXPECT_DOUBLE_EQ(*s.error_budget_percent, 5.0);
  EXPECT_FALSE(s.technique_named);
  for (const auto& [name, tail, says] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"both.json", R"(, "error_budget_pct": 5, "technique": "raymarch"})", "give one"},
           {"zero.json", R"(, "error_budget_pct": 0})", "error_budget_pct"},
           {"huge.json", R"(, "error_budget_pct": 5000})", "error_budget_pct"}}) {
    try {
      load_flight_script(write(name, base + tail));
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(checked_error_budget(-1, "--error-budget"), InputError);
  EXPECT_THROW(checked_error_budget(std::nan(""), "--error-budget"), InputError);
  EXPECT_DOUBLE_EQ(checked_error_budget(2.5, "--error-budget"), 2.5);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
