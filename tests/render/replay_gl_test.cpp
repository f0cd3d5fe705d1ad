// A flight flown by hand, recorded, and replayed from its script renders
// the same frames, byte for byte.
#include "atmosphere/gpu/registry.h"
#include "render/frame.h"

#include "core/data_paths.h"
#include "gl/context.h"
#include "sim/flight_recorder.h"
#include "sim/flight_script.h"
#include "sim/free_flight.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <unistd.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ReplayGLTest, RecordedFlightReplaysByteIdenticalFrames) {
  auto context = GlContext::create_headless();
  Body earth = load_body(data_dir() / "planets" / "earth.json");
  auto model = [&] { return load_atmosphere(earth); };
  const int w = 64, h = 32;
  FrameRenderer live(w, h);
  live.set_body(earth, model(), make_technique("raymarch"));

  // Fly a scripted input at the fixed step with the clock running fast.
  SimClock clock(parse_utc("2026-06-21T17:40:00Z", "test"));
  clock.set_scale(300.0);
  clock.rebase_to_millisecond();
  FreeFlight flight(earth, Geodetic{glm::radians(46.55), glm::radians(7.98), 20.0},
                    glm::radians(250.0));
  const double step = 1.0 / 120.0;
  const double exposure = 6.0;
  FlightRecorder recorder("earth", "raymarch", w, h, 60.0, 10.0, clock.epoch());
  std::vector<std::vector<uint8_t>> flown;
  auto record = [&] {
    Camera c = flight.camera();
    c.vertical_fov = glm::radians(60.0);
    recorder.add(c, clock.elapsed(), exposure);
    live.render(c, sun_dir_body(earth.ephemeris, earth.rotation, clock.utc()), exposure);
    flown.push_back(live.read_ldr());
  };
  record();
  for (int i = 1; i <= 48; ++i) {
    FlightInput in;
    in.move = {0.0, 1.0, 1.0};
    in.turn = {0.3, 0.2 * std::sin(0.1 * i), 0.0};
    in.boost = 10.0;
    clock.advance(step);
    flight.step(step, clock.utc(), in);
    if (i % 12 == 0) record();
  }
  auto file = std::filesystem::temp_directory_path() /
              ("planet_replay_" + std::to_string(::getpid()) + ".json");
  recorder.write(file);
  FlightScript script = load_flight_script(file);
  std::filesystem::remove(file);

  FrameRenderer replay(w, h);
  replay.set_body(script.body, model(), make_technique(script.technique));
  FlightPath path(script);
  ASSERT_EQ(script.frame_count(), int(flown.size()));
  for (int i = 0; i < script.frame_count(); ++i) {
    double t = script.frame_time(i);
    replay.render(path.camera_at(t), path.sun_dir_at(t), path.exposure_at(t));
    EXPECT_EQ(replay.read_ldr(), flown[size_t(i)]) << "frame " << i;
  }
  // The flight went somewhere and the frames show different things.
  EXPECT_NE(flown.front(), flown.back());
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
