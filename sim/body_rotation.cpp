#include "sim/body_rotation.h"

#include "core/json_reader.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace planet {

glm::dmat3 BodyRotation::inertial_from_icrf() const {
  glm::dvec3 pole(std::cos(pole_dec) * std::cos(pole_ra), std::cos(pole_dec) * std::sin(pole_ra),
                  std::sin(pole_dec));
  // The node Q lies on both equators at right ascension pole_ra + 90 deg.
  glm::dvec3 node(-std::sin(pole_ra), std::cos(pole_ra), 0.0);
  glm::dvec3 y = glm::cross(pole, node);
  // Rows are the inertial axes expressed in ICRF.
  return glm::transpose(glm::dmat3(node, y, pole));
}

double BodyRotation::rate() const {
  return sidereal_period > 0 ? 2.0 * glm::pi<double>() / sidereal_period : 0.0;
}

double BodyRotation::angle(UtcSeconds utc) const {
  // UT, not TT: for Earth, W is then the Greenwich mean sidereal time less
  // 90 deg (Meeus 1998, eq. 12.4, its tiny T^2 term left out).
  double turns = sidereal_period > 0 ? utc / sidereal_period : 0.0;
  double frac = turns - std::floor(turns);
  return prime_meridian_j2000 + 2.0 * glm::pi<double>() * frac;
}

glm::dmat3 BodyRotation::body_from_inertial(UtcSeconds utc) const {
  double w = angle(utc);
  double c = std::cos(w), s = std::sin(w);
  // A vector fixed in inertial space turns by -W in the body frame.
  return glm::dmat3(glm::dvec3(c, -s, 0), glm::dvec3(s, c, 0), glm::dvec3(0, 0, 1));
}

BodyRotation parse_rotation(JsonObject rotation) {
  BodyRotation r;
  r.pole_ra = glm::radians(rotation.number("pole_ra_deg", -360.0, 360.0));
  r.pole_dec = glm::radians(rotation.number("pole_dec_deg", -90.0, 90.0));
  r.prime_meridian_j2000 = glm::radians(rotation.number("prime_meridian_j2000_deg", -360.0, 360.0));
  // Negative for a retrograde spin; never zero.
  r.sidereal_period = rotation.number("sidereal_period_s", -1e10, 1e10);
  if (std::abs(r.sidereal_period) < 1.0) {
    rotation.fail("sidereal_period_s", "must be at least one second in magnitude");
  }
  rotation.finish();
  return r;
}

}  // namespace planet
