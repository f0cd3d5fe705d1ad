#include "sim/orbit_flight.h"

namespace planet {

OrbitFlight::OrbitFlight(const Body& body, const KeplerOrbit& orbit, UtcSeconds utc)
    : body_(body), geodesy_(body.shape), orbit_(orbit) {
  // Look a little down toward the horizon ahead.
  orbital_from_camera_ = glm::angleAxis(glm::radians(-20.0), glm::dvec3(1, 0, 0));
  place(utc);
}

void OrbitFlight::place(UtcSeconds utc) {
  utc_ = utc;
  StateVector inertial = orbit_.state_at(utc);
  StateVector s = body_state(body_, inertial, utc);
  glm::dvec3 up = glm::normalize(s.pos);
  glm::dvec3 forward = glm::normalize(s.vel - glm::dot(s.vel, up) * up);
  glm::dvec3 right = glm::cross(forward, up);
  glm::dquat body_from_orbital = glm::quat_cast(glm::dmat3(right, up, -forward));
  camera_.pos_body = s.pos;
  if (ground_) {
    Geodetic g = geodesy_.geodetic_from_body(s.pos);
    double floor = ground_(g) + kGroundClearance;
    if (g.height < floor) {
      g.height = floor;
      camera_.pos_body = geodesy_.body_from_geodetic(g);
    }
  }
  camera_.body_from_camera = glm::normalize(body_from_orbital * orbital_from_camera_);
  speed_ = glm::length(s.vel);
}

void OrbitFlight::set_ground(std::function<double(const Geodetic&)> ground) {
  ground_ = std::move(ground);
  place(utc_);
}

void OrbitFlight::step(double dt, UtcSeconds utc, const FlightInput& input) {
  glm::dvec3 turn = glm::clamp(input.turn, -1.0, 1.0) * (1.2 * dt);
  orbital_from_camera_ = glm::normalize(
      orbital_from_camera_ * glm::angleAxis(turn.x, glm::dvec3(1, 0, 0)) *
      glm::angleAxis(turn.y, glm::dvec3(0, 1, 0)) * glm::angleAxis(turn.z, glm::dvec3(0, 0, -1)));
  place(utc);
}

}  // namespace planet
