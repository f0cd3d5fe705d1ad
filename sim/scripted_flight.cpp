#include "sim/scripted_flight.h"

#include <algorithm>

namespace planet {

ScriptedFlight::ScriptedFlight(FlightScript script)
    : script_(std::make_unique<FlightScript>(std::move(script))),
      path_(std::make_unique<FlightPath>(*script_)),
      time_(script_->keyframes.front().time) {}

void ScriptedFlight::step(double dt, UtcSeconds, const FlightInput&) {
  glm::dvec3 before = path_->camera_at(time_).pos_body;
  time_ = std::min(time_ + dt, script_->keyframes.back().time);
  speed_ = dt > 0 ? glm::length(path_->camera_at(time_).pos_body - before) / dt : 0.0;
}

Camera ScriptedFlight::camera() const { return path_->camera_at(time_); }

}  // namespace planet
