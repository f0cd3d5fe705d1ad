// Flight scripts, written by hand or recorded by `planet fly --record`
// (the same format): loaded, with the terrain's ground under keyframes
// given above it, then flown over their first frames.
#include "fuzz_input.h"
#include "sim/flight_script.h"
#include "sim/scripted_flight.h"
#include "terrain/ground.h"

#include <algorithm>

PLANET_FUZZ_TARGET(flight) {
  std::filesystem::path file = planet::fuzz::write_input(planet::fuzz::as_text(data, size),
                                                         "flight.json");
  planet::fuzz::expect_only_input_errors([&] {
    planet::FlightScript script = planet::load_flight_script(file, planet::terrain_ground());
    int frames = std::min(script.frame_count(), 4);
    double last = script.frame_count() > 0 ? script.frame_time(script.frame_count() - 1) : 0.0;
    planet::ScriptedFlight flight(std::move(script));
    for (int i = 0; i < frames; ++i) {
      flight.step(last / 4.0, flight.utc(), {});
      (void)flight.camera();
      (void)flight.sun_dir_body();
    }
  });
  return 0;
}
