#include "terrain/cube_sphere.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace planet {

glm::dvec3 cube_to_sphere(int face, double s, double t) {
  double x = std::tan(0.25 * glm::pi<double>() * s);
  double y = std::tan(0.25 * glm::pi<double>() * t);
  glm::dvec3 p;
  // Each face's (s, t) axes are chosen so that s x t points outward,
  // giving counter-clockwise triangles seen from outside.
  switch (face) {
    case 0: p = {1, x, y}; break;
    case 1: p = {-1, -x, y}; break;
    case 2: p = {-x, 1, y}; break;
    case 3: p = {x, -1, y}; break;
    case 4: p = {-y, x, 1}; break;
    default: p = {y, x, -1}; break;
  }
  return glm::normalize(p);
}

FacePoint sphere_to_cube(const glm::dvec3& d) {
  glm::dvec3 a = glm::abs(d);
  FacePoint f;
  double x = 0, y = 0;
  // Project onto the face of the largest component, then undo each face's
  // axis choice of cube_to_sphere.
  if (a.x >= a.y && a.x >= a.z) {
    f.face = d.x > 0 ? 0 : 1;
    x = (d.x > 0 ? d.y : -d.y) / a.x;
    y = d.z / a.x;
  } else if (a.y >= a.z) {
    f.face = d.y > 0 ? 2 : 3;
    x = (d.y > 0 ? -d.x : d.x) / a.y;
    y = d.z / a.y;
  } else {
    f.face = d.z > 0 ? 4 : 5;
    x = d.y / a.z;
    y = (d.z > 0 ? -d.x : d.x) / a.z;
  }
  f.s = std::atan(x) * 4.0 / glm::pi<double>();
  f.t = std::atan(y) * 4.0 / glm::pi<double>();
  return f;
}

glm::dvec3 ellipsoid_point(const Ellipsoid& shape, const glm::dvec3& dir) {
  double a = shape.equatorial_radius, b = shape.polar_radius();
  double k = std::sqrt((dir.x * dir.x + dir.y * dir.y) / (a * a) + dir.z * dir.z / (b * b));
  return dir / k;
}

glm::dvec3 ellipsoid_normal(const Ellipsoid& shape, const glm::dvec3& p) {
  double a2 = shape.equatorial_radius * shape.equatorial_radius;
  double b2 = shape.polar_radius() * shape.polar_radius();
  return glm::normalize(glm::dvec3(p.x / a2, p.y / a2, p.z / b2));
}

}  // namespace planet
