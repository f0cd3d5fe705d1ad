// Flight scripts with a clock, orbits and look-at targets: smoothness of
// position and attitude at keyframes, no flip over a pole, the sun
// following the clock, and bad input.
#include "core/data_paths.h"
#include "core/error.h"
#include "sim/attitude_curve.h"
#include "sim/flight_recorder.h"
#include "sim/flight_script.h"
#include "sim/free_flight.h"
#include "terrain/ground.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <fstream>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

class FlightTimingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("planet_timing_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& text) {
    auto p = dir_ / ("flight" + std::to_string(count_++) + ".json");
    std::ofstream(p) << text;
    return p;
  }

  static std::string script(const std::string& top, const std::string& keys) {
    return R"({"body": "earth", "image": {"width": 64, "height": 32}, "frame_rate": 1,)" + top +
           R"(, "keyframes": [)" + keys + "]}";
  }

  void expect_error(const std::string& text, std::vector<std::string> fragments) {
    try {
      load_flight_script(write(text));
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      std::string what = e.what();
      for (const auto& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << what;
    }
  }

  std::filesystem::path dir_;
  int count_ = 0;
};

// Angle between two attitudes, radians.
double angle_between(const glm::dquat& a, const glm::dquat& b) {
  return glm::length(rotation_vector(glm::inverse(a) * b));
}

TEST_F(FlightTimingTest, PositionAndAttitudeAreC1AtKeyframes) {
  FlightScript s = load_flight_script(write(script(R"("start_utc": "2026-06-21T18:00:00Z")", R"(
      {"time": 0, "lat_deg": 10, "lon_deg": 20, "height_m": 100, "heading_deg": 0, "pitch_deg": 5},
      {"time": 3, "lat_deg": 10.1, "lon_deg": 20.2, "height_m": 900, "heading_deg": 60, "pitch_deg": -30, "roll_deg": 20},
      {"time": 5, "lat_deg": 10.3, "lon_deg": 20.3, "height_m": 5000, "look_at": {"lat_deg": 10.5, "lon_deg": 20.5}},
      {"time": 9, "lat_deg": 10.4, "lon_deg": 20.6, "height_m": 3000, "heading_deg": 200, "pitch_deg": -89})")));
  FlightPath path(s);
  const double eps = 1e-5;
  for (size_t i = 1; i + 1 < s.keyframes.size(); ++i) {
    double t = s.keyframes[i].time;
    Camera before = path.camera_at(t - eps), at = path.camera_at(t),
           after = path.camera_at(t + eps);
    // Continuity: both sides close to the keyframe.
    EXPECT_LT(glm::length(before.pos_body - at.pos_body), 1.0) << i;
    EXPECT_LT(glm::length(after.pos_body - at.pos_body), 1.0) << i;
    // First derivative: the one-sided velocities agree.
    Camera before2 = path.camera_at(t - 2 * eps), after2 = path.camera_at(t + 2 * eps);
    glm::dvec3 v_left = (before.pos_body - before2.pos_body) / eps;
    glm::dvec3 v_right = (after2.pos_body - after.pos_body) / eps;
    EXPECT_LT(glm::length(v_left - v_right), 1e-3 * glm::length(v_left) + 1e-2) << i;
    glm::dvec3 w_left =
        rotation_vector(glm::inverse(before2.body_from_camera) * before.body_from_camera) / eps;
    glm::dvec3 w_right =
        rotation_vector(glm::inverse(after.body_from_camera) * after2.body_from_camera) / eps;
    EXPECT_LT(glm::length(w_left - w_right), 1e-3 * glm::length(w_left) + 1e-4) << i;
    EXPECT_LT(angle_between(before.body_from_camera, at.body_from_camera), 1e-4) << i;
  }
}

TEST_F(FlightTimingTest, AttitudeThroughThePoleDoesNotFlip) {
  // Over the north pole, looking straight down, then along the flight:
  // heading jumps 180 deg across the pole, the camera must not.
  FlightScript s =
      load_flight_script(write(script(R"("sun": {"elevation_deg": 20, "azimuth_deg": 0})", R"(
      {"time": 0, "lat_deg": 89.0, "lon_deg": 0, "height_m": 20000, "heading_deg": 0, "pitch_deg": -60},
      {"time": 4, "lat_deg": 90.0, "lon_deg": 0, "height_m": 20000, "heading_deg": 0, "pitch_deg": -90},
      {"time": 8, "lat_deg": 89.0, "lon_deg": 180, "height_m": 20000, "heading_deg": 180, "pitch_deg": -60})")));
  FlightPath path(s);
  glm::dquat previous = path.camera_at(0).body_from_camera;
  double largest = 0;
  for (int i = 1; i <= 800; ++i) {
    glm::dquat q = path.camera_at(i * 0.01).body_from_camera;
    largest = std::max(largest, angle_between(previous, q));
    previous = q;
  }
  // The whole flight turns 60 deg; no 10 ms step may turn more than 1 deg.
  EXPECT_LT(glm::degrees(largest), 1.0);
  // Straight down at the pole the camera looks along -up.
  Camera pole = path.camera_at(4.0);
  EXPECT_NEAR(glm::dot(pole.forward_body(), glm::normalize(pole.pos_body)), -1.0, 1e-9);
}

TEST_F(FlightTimingTest, OrbitSegmentFollowsKeplerAndJoinsSmoothly) {
  FlightScript s = load_flight_script(write(script(R"("start_utc": "2026-03-20T06:00:00Z")", R"(
      {"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 380000, "heading_deg": 60},
      {"time": 60, "lat_deg": 1, "lon_deg": 3, "height_m": 400000, "orbit": {"inclination_deg": 51.6}, "heading_deg": 60},
      {"time": 1500, "heading_deg": 120},
      {"time": 1600, "lat_deg": 40, "lon_deg": 100, "height_m": 420000})")));
  FlightPath path(s);
  // Inside the orbit: constant radius (a circle) at orbital speed.
  Geodesy geodesy(s.body.shape);
  double r0 = glm::length(path.camera_at(100).pos_body);
  EXPECT_NEAR(glm::length(path.camera_at(900).pos_body), r0, 1e-3);
  // Both junctions are C1 in position.
  for (double t : {60.0, 1500.0}) {
    const double eps = 1e-3;
    glm::dvec3 a = path.camera_at(t - 2 * eps).pos_body, b = path.camera_at(t - eps).pos_body;
    glm::dvec3 c = path.camera_at(t + eps).pos_body, d = path.camera_at(t + 2 * eps).pos_body;
    glm::dvec3 v_left = (b - a) / eps, v_right = (d - c) / eps;
    EXPECT_GT(glm::length(v_left), 7000.0) << t;
    EXPECT_LT(glm::length(v_left - v_right) / glm::length(v_left), 1e-3) << t;
  }
  // The sun moves with the clock: 25 minutes turn the Earth ~6 deg.
  double turned = std::acos(glm::dot(path.sun_dir_at(0), path.sun_dir_at(1500)));
  EXPECT_NEAR(glm::degrees(turned), 1500.0 / 86164.0 * 360.0, 0.1);
}

TEST_F(FlightTimingTest, KeyframeClockDrivesTheSun) {
  // A sunset in ten seconds: two hours of clock between keyframes.
  FlightScript s = load_flight_script(write(script(R"("start_utc": "2026-06-21T18:30:00Z")", R"(
      {"time": 0, "lat_deg": 48.85, "lon_deg": 2.35, "height_m": 10},
      {"time": 10, "lat_deg": 48.85, "lon_deg": 2.35, "height_m": 10, "utc": "2026-06-21T20:30:00Z"})")));
  FlightPath path(s);
  EXPECT_DOUBLE_EQ(path.utc_at(5.0), parse_utc("2026-06-21T19:30:00Z", "t"));
  double e0 = horizon_angles(path.sun_dir_at(0), glm::radians(48.85), glm::radians(2.35)).elevation;
  double e1 =
      horizon_angles(path.sun_dir_at(10), glm::radians(48.85), glm::radians(2.35)).elevation;
  EXPECT_GT(e0, glm::radians(5.0));
  EXPECT_LT(e1, 0.0);  // Paris sunset is near 19:58 UTC at midsummer
}

TEST_F(FlightTimingTest, RecordedFlightReplaysTheExactCameraAndSun) {
  Body earth = load_body(find_body_file("earth"));
  SimClock clock(parse_utc("2026-06-21T10:00:00Z", "t"));
  clock.set_scale(100.0);
  FreeFlight flight(earth, Geodetic{glm::radians(46.5), glm::radians(8.0), 50.0}, 1.0);
  clock.rebase_to_millisecond();
  const double step = 1.0 / 120.0;
  FlightRecorder recorder("earth", "raymarch", 64, 32, 60.0, 10.0, clock.epoch());
  std::vector<Camera> flown;
  std::vector<glm::dvec3> suns;
  auto record = [&] {
    recorder.add(flight.camera(), clock.elapsed(), 4.0);
    flown.push_back(flight.camera());
    suns.push_back(sun_dir_body(earth.ephemeris, earth.rotation, clock.utc()));
  };
  record();
  for (int i = 1; i <= 120; ++i) {
    FlightInput in;
    in.move = {0.3, 0.5 * std::sin(i * 0.1), 1.0};
    in.turn = {0.2, -0.4, 0.1 * std::cos(i * 0.05)};
    clock.advance(step);
    flight.step(step, clock.utc(), in);
    if (i % 12 == 0) record();
  }
  auto file = dir_ / "recorded.json";
  recorder.write(file);
  FlightScript s = load_flight_script(file);
  ASSERT_EQ(s.frame_count(), int(flown.size()));
  FlightPath path(s);
  for (int i = 0; i < s.frame_count(); ++i) {
    Camera c = path.camera_at(s.frame_time(i));
    EXPECT_EQ(c.pos_body, flown[size_t(i)].pos_body) << i;
    EXPECT_EQ(c.body_from_camera, flown[size_t(i)].body_from_camera) << i;
    EXPECT_EQ(path.sun_dir_at(s.frame_time(i)), suns[size_t(i)]) << i;
    EXPECT_EQ(path.exposure_at(s.frame_time(i)), 4.0);
  }
}

TEST_F(FlightTimingTest, BadTimesOrbitsAndTargetsAreClearErrors) {
  const std::string key = R"({"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 10})";
  expect_error(script(R"("start_utc": "2026-06-31T00:00:00Z")", key), {"start_utc", "2026-06-31"});
  expect_error(script(R"("start_utc": "tomorrow")", key), {"start_utc", "tomorrow", "UTC"});
  expect_error(
      script(
          R"("start_utc": "2026-06-21T00:00:00Z", "sun": {"elevation_deg": 1, "azimuth_deg": 1})",
          key),
      {"either", "start_utc", "sun"});
  expect_error(script(R"("exposure": 1)", key), {"either"});
  expect_error(
      script(
          R"("sun": {"elevation_deg": 1, "azimuth_deg": 1})",
          R"({"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 10, "utc": "2026-01-01T00:00:00Z"})"),
      {"keyframes[0]", "start_utc"});
  expect_error(
      script(
          R"("start_utc": "2026-06-21T00:00:00Z")",
          R"({"time": 0, "lat_deg": 60, "lon_deg": 0, "height_m": 400000, "orbit": {"inclination_deg": 30}},
                         {"time": 10})"),
      {"keyframes[0].orbit", "never reaches latitude"});
  expect_error(
      script(
          R"("start_utc": "2026-06-21T00:00:00Z")",
          R"({"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 400000, "orbit": {"inclination_deg": 30}},
                         {"time": 10, "lat_deg": 1, "lon_deg": 1, "height_m": 1})"),
      {"keyframes[1].lat_deg", "orbit"});
  expect_error(
      script(
          R"("start_utc": "2026-06-21T00:00:00Z")",
          R"({"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 400000, "orbit": {"inclination_deg": 30}})"),
      {"keyframes[0].orbit", "keyframe after"});
  expect_error(script(R"("start_utc": "2026-06-21T00:00:00Z")",
                      R"({"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": -5000000})"),
               {"keyframes[0].height_m", "out of range"});
  expect_error(
      script(
          R"("start_utc": "2026-06-21T00:00:00Z")",
          R"({"time": 0, "lat_deg": 0, "lon_deg": 0, "height_m": 0, "look_at": {"lat_deg": 0, "lon_deg": 0}})"),
      {"keyframes[0].look_at", "where the camera is"});
}

TEST_F(FlightTimingTest, ShippedFlightsStayAboveGroundAndShowWhatTheyPromise) {
  for (const char* name : {"ascent", "mars_sunset", "asteroid_landing", "earth_orbit_terminator"}) {
    SCOPED_TRACE(name);
    const GroundHeight ground = terrain_ground();
    FlightScript s =
        load_flight_script(data_dir() / "flights" / (std::string(name) + ".json"), ground);
    FlightPath path(s);
    EXPECT_GE(s.frame_count(), 30);
    // Every frame, not only the keyframes, a metre or more above the ground.
    for (int i = 0; i < s.frame_count(); ++i) {
      Geodetic place = path.place_at(s.frame_time(i));
      EXPECT_GT(place.height - ground(s.body, place), 1.0) << "frame " << i;
    }
  }
  // The Mars sunset starts with the sun up and ends with it set.
  FlightScript mars =
      load_flight_script(data_dir() / "flights" / "mars_sunset.json", terrain_ground());
  FlightPath mars_path(mars);
  auto elevation = [](const FlightPath& p, double t) {
    Geodetic g = p.place_at(t);
    return glm::degrees(horizon_angles(p.sun_dir_at(t), g.lat, g.lon).elevation);
  };
  EXPECT_GT(elevation(mars_path, 0.0), 5.0);
  EXPECT_LT(elevation(mars_path, mars.duration()), 0.0);
  // The orbit crosses the terminator from day into night, and ends as the
  // sun sets behind the limb: night on the ground below, the sun still
  // above the horizon seen from 400 km (which dips 19.7 deg).
  FlightScript orbit = load_flight_script(data_dir() / "flights" / "earth_orbit_terminator.json");
  FlightPath orbit_path(orbit);
  EXPECT_GT(elevation(orbit_path, 0.0), 30.0);
  double end = elevation(orbit_path, orbit.duration());
  EXPECT_LT(end, -10.0);
  EXPECT_GT(end, -19.7);
}

TEST_F(FlightTimingTest, AClockedFlightSaysWhereTheMoonOrTheEarthIs) {
  // Over Earth, the Moon; over the Moon, the Earth: each where it really is
  // at the flight's clock (356 400 to 406 700 km apart, perigee to apogee).
  auto expect_companion = [](const char* name) {
    SCOPED_TRACE(name);
    FlightScript s = load_flight_script(data_dir() / "flights" / (std::string(name) + ".json"),
                                        terrain_ground());
    FlightPath path(s);
    for (double t : {0.0, s.duration()}) {
      std::optional<glm::dvec3> other = path.companion_pos_at(t);
      ASSERT_TRUE(other);
      EXPECT_GT(glm::length(*other), 356.0e6);
      EXPECT_LT(glm::length(*other), 407.0e6);
      EXPECT_EQ(*other, *companion_pos_body(s.body.ephemeris, s.body.rotation, path.utc_at(t)));
    }
  };
  expect_companion("earth_orbit_terminator");
  expect_companion("moon_descent");
  // A script whose sun is given by hand has no clock, and so no Moon.
  FlightScript plain = load_flight_script(data_dir() / "flights" / "ascent.json", terrain_ground());
  ASSERT_FALSE(plain.has_clock);
  EXPECT_FALSE(FlightPath(plain).companion_pos_at(0.0));
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
