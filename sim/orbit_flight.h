#pragma once
// Orbit: the camera rides a Kepler orbit while the body turns under it.
// The pilot only turns the camera, relative to the local orbital frame
// (forward along the velocity, up away from the body).
#include "sim/flight_controller.h"
#include "sim/geodesy.h"
#include "sim/kepler.h"

#include <functional>

namespace planet {

class OrbitFlight : public FlightController {
 public:
  OrbitFlight(const Body& body, const KeplerOrbit& orbit, UtcSeconds utc);

  void step(double dt, UtcSeconds utc, const FlightInput& input) override;
  Camera camera() const override { return camera_; }
  double speed() const override { return speed_; }
  const KeplerOrbit& orbit() const { return orbit_; }
  // The surface's height above the ellipsoid at a place: where the orbit
  // passes below it plus a clearance (a low orbit over mountains), the
  // camera is held above it along the vertical while the orbit runs on.
  void set_ground(std::function<double(const Geodetic&)> ground);

 private:
  void place(UtcSeconds utc);

  Body body_;
  Geodesy geodesy_;
  KeplerOrbit orbit_;
  std::function<double(const Geodetic&)> ground_;
  // Camera attitude relative to the orbital frame (x right, y up, -z along
  // the velocity).
  glm::dquat orbital_from_camera_{1, 0, 0, 0};
  Camera camera_;
  double speed_ = 0;
  UtcSeconds utc_ = 0;
  static constexpr double kGroundClearance = 0.5;  // metres, as free flight's
};

}  // namespace planet
