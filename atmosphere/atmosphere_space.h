#pragma once
// The atmosphere model is a spherical shell; Earth and Mars are oblate.
// Atmosphere space is the body frame scaled by diag(k, k, k a/b) with
// k = bottom_radius / a, which maps the body's ellipsoid exactly onto the
// shell's bottom sphere: the sky then meets the ground everywhere (at the
// poles and the equator alike) and the limb seen from orbit hugs the
// planet's silhouette. The distortion is 0.34% for Earth, well below what
// the shading can show.
#include "sim/body.h"

#include <glm/glm.hpp>

namespace planet {

inline glm::dvec3 atmosphere_scale(const Ellipsoid& shape, double bottom_radius) {
  double k = bottom_radius / shape.equatorial_radius;
  return {k, k, k * shape.equatorial_radius / shape.polar_radius()};
}

}  // namespace planet
