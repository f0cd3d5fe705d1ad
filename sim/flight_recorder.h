#pragma once
// Records a flight as it is flown into a flight script that `planet
// capture` replays exactly: one keyframe per captured frame, holding the
// camera's body-frame position and attitude as doubles (JSON keeps every
// bit), the clock as seconds after the start and the exposure. At those
// instants FlightPath returns the keyframe itself, so each replayed frame
// sees the very camera and sun that were flown.
#include "sim/camera.h"
#include "sim/utc_time.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace planet {

class FlightRecorder {
 public:
  // `start` must be a millisecond instant (SimClock::rebase_to_millisecond).
  FlightRecorder(std::string body, std::string technique, int width, int height,
                 double vertical_fov_deg, double frame_rate, UtcSeconds start);

  // Frame i is due at i / frame_rate seconds of flight.
  double next_frame_time() const { return double(frames_) / frame_rate_; }
  void add(const Camera& camera, double clock_s, double exposure);
  int frames() const { return frames_; }

  nlohmann::json script() const;
  void write(const std::filesystem::path& file) const;

 private:
  nlohmann::json script_;
  double frame_rate_;
  int frames_ = 0;
};

}  // namespace planet
