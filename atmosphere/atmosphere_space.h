#pragma once
// The atmosphere model is a spherical shell; Earth and Mars are oblate.
// Atmosphere space is the body frame scaled by diag(k, k, k a/b) with
// k = bottom_radius / a, which maps the body's ellipsoid exactly onto the
// shell's bottom sphere: the sky then meets the ground everywhere (at the
// poles and the equator alike) and the limb seen from orbit hugs the
// planet's silhouette. The distortion is 0.34% for Earth, well below what
// the shading can show.
#include "sim/body.h"
#include "sim/camera.h"

#include <glm/glm.hpp>
#include <glm/gtx/matrix_operation.hpp>

namespace planet {

inline glm::dvec3 atmosphere_scale(const Ellipsoid& shape, double bottom_radius) {
  double k = bottom_radius / shape.equatorial_radius;
  return {k, k, k * shape.equatorial_radius / shape.polar_radius()};
}

// The camera's rays in atmosphere space: (ndc.x, ndc.y, 1) -> view ray ->
// body -> atmosphere space (a linear map, so rays stay rays), unnormalised,
// of length the atmosphere-space distance per unit of view depth. The
// frame's sky and the ground truth's camera are both this one map.
inline glm::dmat3 atmo_ray_from_ndc(const glm::dvec3& scale, const Camera& camera, double aspect) {
  glm::dmat3 body_from_view = glm::mat3_cast(camera.body_from_camera);
  return glm::dmat3(glm::diagonal3x3(scale)) * body_from_view *
         view_ray_from_ndc(camera.vertical_fov, aspect);
}

}  // namespace planet
