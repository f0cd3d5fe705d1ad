#pragma once
// A body's spin: the IAU model (Archinal et al. 2018, "Report of the IAU
// Working Group on Cartographic Coordinates and Rotational Elements") with
// a fixed pole and a uniform rotation. The body-fixed frame turns about the
// pole by W(t) = W0 + 360 deg * t / sidereal period, W measured from the
// node of the body's equator on the ICRF equator.
#include "sim/utc_time.h"

#include <glm/glm.hpp>

namespace planet {

class JsonObject;

struct BodyRotation {
  double pole_ra = 0;  // radians, ICRF
  double pole_dec = glm::radians(90.0);
  double prime_meridian_j2000 = 0;   // W0, radians
  double sidereal_period = 86400.0;  // seconds; the frame is fixed when 0

  // The body's inertial equatorial frame: z the pole, x the ascending node
  // of the body's equator on the ICRF equator.
  glm::dmat3 inertial_from_icrf() const;
  // W at `utc`, radians.
  double angle(UtcSeconds utc) const;
  // Rotates inertial equatorial vectors into the body-fixed frame.
  glm::dmat3 body_from_inertial(UtcSeconds utc) const;
  // The angular velocity of the body-fixed frame, radians per second.
  double rate() const;
};

// Reads the "rotation" object of a body file.
BodyRotation parse_rotation(JsonObject rotation);

}  // namespace planet
