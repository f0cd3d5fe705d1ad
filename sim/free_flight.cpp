#include "sim/free_flight.h"

#include <algorithm>
#include <cmath>

namespace planet {

FreeFlight::FreeFlight(const Body& body, const Geodetic& place, double heading)
    : geodesy_(body.shape), ground_([](const Geodetic&) { return 0.0; }) {
  camera_.pos_body = geodesy_.body_from_geodetic(place);
  camera_.body_from_camera = glm::normalize(glm::quat_cast(geodesy_.body_from_enu(place)) *
                                            enu_from_camera(heading, 0.0, 0.0));
}

FreeFlight::FreeFlight(const Body& body, const Camera& camera)
    : geodesy_(body.shape), camera_(camera), ground_([](const Geodetic&) { return 0.0; }) {}

void FreeFlight::set_ground(std::function<double(const Geodetic&)> ground) {
  ground_ = std::move(ground);
  keep_above_ground();
}

void FreeFlight::keep_above_ground() {
  Geodetic g = geodesy_.geodetic_from_body(camera_.pos_body);
  double floor = ground_(g) + kClearance;
  if (g.height < floor) {
    g.height = floor;
    camera_.pos_body = geodesy_.body_from_geodetic(g);
  }
}

double FreeFlight::height_above_ground() const {
  Geodetic g = geodesy_.geodetic_from_body(camera_.pos_body);
  return g.height - ground_(g);
}

void FreeFlight::step(double dt, UtcSeconds, const FlightInput& input) {
  // Turn in the camera's own axes: no gimbal, no special case at the poles.
  glm::dvec3 turn = glm::clamp(input.turn, -1.0, 1.0) * (kTurnRate * dt);
  glm::dquat delta = glm::angleAxis(turn.x, glm::dvec3(1, 0, 0)) *
                     glm::angleAxis(turn.y, glm::dvec3(0, 1, 0)) *
                     glm::angleAxis(turn.z, glm::dvec3(0, 0, -1));
  camera_.body_from_camera = glm::normalize(camera_.body_from_camera * delta);

  double height = std::max(height_above_ground(), 0.0);
  double max_speed =
      std::clamp(kSpeedPerHeight * height, kMinSpeed, kMaxSpeed) * std::max(input.boost, 0.0);
  glm::dvec3 move = glm::clamp(input.move, -1.0, 1.0);
  glm::dvec3 dir_camera(move.x, move.y, -move.z);
  glm::dvec3 displacement = camera_.body_from_camera * dir_camera * (max_speed * dt);
  glm::dvec3 before = camera_.pos_body;
  camera_.pos_body += displacement;

  keep_above_ground();  // never into the ground
  speed_ = dt > 0 ? glm::length(camera_.pos_body - before) / dt : 0.0;
}

}  // namespace planet
