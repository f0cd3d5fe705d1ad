#include "sim/flight_controller.h"

#include <algorithm>

namespace planet {

int FixedStep::advance(double real_seconds, int max_steps) {
  carried_ += real_seconds;
  int steps = int(carried_ / step_);
  carried_ -= steps * step_;
  if (steps > max_steps) {
    steps = max_steps;
    carried_ = 0;
  }
  return std::max(steps, 0);
}

}  // namespace planet
