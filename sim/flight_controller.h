#pragma once
// The one interface behind which the camera is flown: by hand (free
// flight), by gravity (an orbit) or by a script. The simulation advances it
// in fixed steps (FixedStep), so that the same inputs give the same flight
// whatever the frame rate.
#include "sim/body.h"
#include "sim/camera.h"
#include "sim/utc_time.h"

#include <glm/glm.hpp>

namespace planet {

// A pilot's commands, each axis in [-1, 1].
struct FlightInput {
  glm::dvec3 move{0.0};  // along camera x (right), y (up), -z (forward)
  glm::dvec3 turn{0.0};  // rates about camera x (pitch up), y (yaw left), -z (roll right)
  double boost = 1.0;    // speed multiplier
};

class FlightController {
 public:
  virtual ~FlightController() = default;
  // Advances by `dt` seconds of simulated time, ending at `utc`.
  virtual void step(double dt, UtcSeconds utc, const FlightInput& input) = 0;
  virtual Camera camera() const = 0;
  // Speed over the body's surface frame, metres per second.
  virtual double speed() const = 0;
};

// Turns real elapsed time into whole simulation steps of fixed length.
class FixedStep {
 public:
  explicit FixedStep(double step) : step_(step) {}
  // The number of steps to take now; the remainder carries over. At most
  // `max_steps` so that a long stall does not freeze the program.
  int advance(double real_seconds, int max_steps = 8);
  double step() const { return step_; }

 private:
  double step_;
  double carried_ = 0;
};

}  // namespace planet
