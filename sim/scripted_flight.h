#pragma once
// A flight script flown as a controller: each step advances the script's
// own time, so the window shows what `planet capture` would render. The
// pilot's input is ignored; the clock is the script's.
#include "sim/flight_controller.h"
#include "sim/flight_script.h"

#include <memory>

namespace planet {

class ScriptedFlight : public FlightController {
 public:
  explicit ScriptedFlight(FlightScript script);

  void step(double dt, UtcSeconds utc, const FlightInput& input) override;
  Camera camera() const override;
  double speed() const override { return speed_; }

  double time() const { return time_; }
  bool finished() const { return time_ >= script_->keyframes.back().time; }
  UtcSeconds utc() const { return path_->utc_at(time_); }
  glm::dvec3 sun_dir_body() const { return path_->sun_dir_at(time_); }
  double exposure() const { return path_->exposure_at(time_); }

 private:
  // Held by pointer: FlightPath keeps a pointer to its script.
  std::unique_ptr<FlightScript> script_;
  std::unique_ptr<FlightPath> path_;
  double time_ = 0;
  double speed_ = 0;
};

}  // namespace planet
