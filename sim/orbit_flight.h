#pragma once
// Orbit: the camera rides a Kepler orbit while the body turns under it.
// The pilot only turns the camera, relative to the local orbital frame
// (forward along the velocity, up away from the body).
#include "sim/flight_controller.h"
#include "sim/kepler.h"

namespace planet {

class OrbitFlight : public FlightController {
 public:
  OrbitFlight(const Body& body, const KeplerOrbit& orbit, UtcSeconds utc);

  void step(double dt, UtcSeconds utc, const FlightInput& input) override;
  Camera camera() const override { return camera_; }
  double speed() const override { return speed_; }
  const KeplerOrbit& orbit() const { return orbit_; }

 private:
  void place(UtcSeconds utc);

  Body body_;
  KeplerOrbit orbit_;
  // Camera attitude relative to the orbital frame (x right, y up, -z along
  // the velocity).
  glm::dquat orbital_from_camera_{1, 0, 0, 0};
  Camera camera_;
  double speed_ = 0;
};

}  // namespace planet
