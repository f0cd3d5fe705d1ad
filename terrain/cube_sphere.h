#pragma once
// The cube-sphere: six cube faces mapped onto the body's ellipsoid. Every
// terrain tile is a square of one face's (s, t) parameter plane, so tiles
// of all levels share their grid points exactly.
#include "sim/body.h"

#include <glm/glm.hpp>

namespace planet {

// The unit-cube face point (face 0..5, s and t in [-1, 1]) to a unit
// direction, through the tangent warp tan(pi/4 s) that evens out cell
// sizes: largest to smallest cell area 1.41 against 5.2 for plain
// normalisation of the cube point.
glm::dvec3 cube_to_sphere(int face, double s, double t);

// The inverse: the face a direction falls on and its (s, t) there.
struct FacePoint {
  int face = 0;
  double s = 0, t = 0;
};
FacePoint sphere_to_cube(const glm::dvec3& dir);

// The point of the ellipsoid in geocentric direction `dir`.
glm::dvec3 ellipsoid_point(const Ellipsoid& shape, const glm::dvec3& dir);
glm::dvec3 ellipsoid_normal(const Ellipsoid& shape, const glm::dvec3& point);

}  // namespace planet
