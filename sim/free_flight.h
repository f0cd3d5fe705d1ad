#pragma once
// Free flight: six degrees of freedom in the body-fixed frame, speed scaled
// with the height above the surface (0.2 m/s per metre of height, and never
// slower than a brisk walk near the ground; thousands of km per second far
// out), never below a clearance above the surface.
#include "sim/flight_controller.h"
#include "sim/geodesy.h"

#include <functional>

namespace planet {

class FreeFlight : public FlightController {
 public:
  // Starts at `place`, looking along `heading` (radians), level. The place
  // is taken as it is (a small body's ground lies below its ellipsoid in
  // places): set_ground lifts it where it is below the ground.
  FreeFlight(const Body& body, const Geodetic& place, double heading);
  FreeFlight(const Body& body, const Camera& camera);

  void step(double dt, UtcSeconds utc, const FlightInput& input) override;
  Camera camera() const override { return camera_; }
  double speed() const override { return speed_; }

  // The surface's height above the ellipsoid at a place (0 until a terrain
  // gives one); a camera below it plus the clearance is lifted at once.
  void set_ground(std::function<double(const Geodetic&)> ground);
  double height_above_ground() const;

  static constexpr double kClearance = 0.5;       // metres above the surface
  static constexpr double kSpeedPerHeight = 0.2;  // per second
  // Metres per second: a brisk walk. Height-scaled alone, 2 m above the
  // ground gave 0.4 m/s, and four seconds of W moved the pilot 1.6 m.
  static constexpr double kMinSpeed = 1.5;
  static constexpr double kMaxSpeed = 5.0e6;      // metres per second
  static constexpr double kTurnRate = 1.2;        // radians per second at full input

 private:
  Geodesy geodesy_;
  Camera camera_;
  double speed_ = 0;
  // Lifts the camera along the vertical to the clearance above the ground.
  void keep_above_ground();

  std::function<double(const Geodetic&)> ground_;
};

}  // namespace planet
