#include "sim/kepler.h"

#include "core/error.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace planet {

namespace {

constexpr double kTwoPi = 2.0 * glm::pi<double>();

// Newton's method on E - e sin E = M, started at M (e < 0.8) or pi.
double eccentric_anomaly(double mean_anomaly, double e) {
  double m = std::remainder(mean_anomaly, kTwoPi);
  double big_e = e < 0.8 ? m : glm::pi<double>() * (m < 0 ? -1.0 : 1.0);
  for (int i = 0; i < 50; ++i) {
    double f = big_e - e * std::sin(big_e) - m;
    double step = f / (1.0 - e * std::cos(big_e));
    big_e -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return big_e;
}

}  // namespace

double orbital_energy(const StateVector& s, double mu) {
  return 0.5 * glm::dot(s.vel, s.vel) - mu / glm::length(s.pos);
}

glm::dvec3 angular_momentum(const StateVector& s) { return glm::cross(s.pos, s.vel); }

KeplerOrbit KeplerOrbit::from_state(const StateVector& state, double mu, double epoch) {
  if (mu <= 0) throw InputError("an orbit needs the body's gm_m3_s2");
  double r = glm::length(state.pos);
  glm::dvec3 h = angular_momentum(state);
  double energy = orbital_energy(state, mu);
  if (!(energy < 0)) throw InputError("the state is not a bound orbit (escape speed or more)");
  if (glm::length(h) <= 1e-12 * r * glm::length(state.vel)) {
    throw InputError("the state is a straight fall, not an orbit");
  }
  KeplerOrbit o;
  o.mu_ = mu;
  o.epoch_ = epoch;
  o.a_ = -mu / (2.0 * energy);
  // Eccentricity vector, pointing at periapsis.
  glm::dvec3 e_vec = ((glm::dot(state.vel, state.vel) - mu / r) * state.pos -
                      glm::dot(state.pos, state.vel) * state.vel) /
                     mu;
  o.e_ = glm::length(e_vec);
  glm::dvec3 w = glm::normalize(h);
  // A circle has no periapsis: measure from the current position instead.
  o.p_ = o.e_ > 1e-12 ? e_vec / o.e_ : state.pos / r;
  if (o.e_ <= 1e-12) o.e_ = 0;
  o.q_ = glm::cross(w, o.p_);
  double nu = std::atan2(glm::dot(state.pos, o.q_), glm::dot(state.pos, o.p_));
  double big_e = std::atan2(std::sqrt(1.0 - o.e_ * o.e_) * std::sin(nu), o.e_ + std::cos(nu));
  o.mean_anomaly0_ = big_e - o.e_ * std::sin(big_e);
  return o;
}

KeplerOrbit KeplerOrbit::from_elements(const OrbitalElements& el, double mu, double epoch) {
  if (mu <= 0) throw InputError("an orbit needs the body's gm_m3_s2");
  if (!(el.eccentricity >= 0 && el.eccentricity < 1)) {
    throw InputError(
        fmt::format("eccentricity {} is not that of an ellipse [0, 1)", el.eccentricity));
  }
  if (!(el.semi_major_axis > 0)) throw InputError("the semi-major axis must be positive");
  KeplerOrbit o;
  o.mu_ = mu;
  o.epoch_ = epoch;
  o.a_ = el.semi_major_axis;
  o.e_ = el.eccentricity;
  o.mean_anomaly0_ = el.mean_anomaly;
  // Perifocal axes in the inertial frame: R3(-Omega) R1(-i) R3(-omega).
  double co = std::cos(el.ascending_node), so = std::sin(el.ascending_node);
  double ci = std::cos(el.inclination), si = std::sin(el.inclination);
  double cw = std::cos(el.periapsis_arg), sw = std::sin(el.periapsis_arg);
  o.p_ = {co * cw - so * sw * ci, so * cw + co * sw * ci, sw * si};
  o.q_ = {-co * sw - so * cw * ci, -so * sw + co * cw * ci, cw * si};
  return o;
}

double KeplerOrbit::period() const { return kTwoPi * std::sqrt(a_ * a_ * a_ / mu_); }

StateVector KeplerOrbit::state_at(double time) const {
  double n = std::sqrt(mu_ / (a_ * a_ * a_));
  double big_e = eccentric_anomaly(mean_anomaly0_ + n * (time - epoch_), e_);
  double c = std::cos(big_e), s = std::sin(big_e);
  double b = std::sqrt(1.0 - e_ * e_);
  double rate = n / (1.0 - e_ * c);  // dE/dt
  StateVector st;
  st.pos = a_ * (c - e_) * p_ + a_ * b * s * q_;
  st.vel = -a_ * s * rate * p_ + a_ * b * c * rate * q_;
  return st;
}

KeplerOrbit circular_orbit_over(const Body& body, const Geodetic& place, double inclination,
                                bool northbound, UtcSeconds utc) {
  if (body.gm <= 0) throw InputError(body.name + " has no gm_m3_s2: it cannot be orbited");
  Geodesy geodesy(body.shape);
  glm::dvec3 pos_body = geodesy.body_from_geodetic(place);
  glm::dmat3 inertial_from_body = glm::transpose(body.rotation.body_from_inertial(utc));
  glm::dvec3 r = inertial_from_body * pos_body;
  double radius = glm::length(r);
  glm::dvec3 up = r / radius;
  double cos_lat = std::sqrt(up.x * up.x + up.y * up.y);
  if (cos_lat < 1e-9) throw InputError("a circular orbit cannot start over a pole");
  glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up));
  glm::dvec3 north = glm::cross(up, east);
  // Spherical trigonometry of the ground track: sin(azimuth) cos(lat) = cos(i).
  double sin_az = std::cos(inclination) / cos_lat;
  if (std::abs(sin_az) > 1.0 + 1e-12) {
    throw InputError(fmt::format("an orbit inclined {:.2f} deg never reaches latitude {:.2f} deg",
                                 glm::degrees(inclination), glm::degrees(std::acos(cos_lat))));
  }
  sin_az = glm::clamp(sin_az, -1.0, 1.0);
  double cos_az = std::sqrt(1.0 - sin_az * sin_az) * (northbound ? 1.0 : -1.0);
  StateVector s;
  s.pos = r;
  s.vel = std::sqrt(body.gm / radius) * (sin_az * east + cos_az * north);
  return KeplerOrbit::from_state(s, body.gm, utc);
}

StateVector body_state(const Body& body, const StateVector& inertial, UtcSeconds utc) {
  glm::dmat3 body_from_inertial = body.rotation.body_from_inertial(utc);
  StateVector s;
  s.pos = body_from_inertial * inertial.pos;
  // v_body = R (v - omega x r), omega along the pole.
  glm::dvec3 omega(0, 0, body.rotation.rate());
  s.vel = body_from_inertial * (inertial.vel - glm::cross(omega, inertial.pos));
  return s;
}

}  // namespace planet
