#include "terrain/ellipsoid_mesh.h"

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

PatchMesh make_ellipsoid_mesh(const Ellipsoid& shape, int patches_per_edge, int quads_per_patch) {
  PatchMesh mesh;
  const int n = quads_per_patch + 1;
  for (int j = 0; j < quads_per_patch; ++j) {
    for (int i = 0; i < quads_per_patch; ++i) {
      uint32_t v00 = uint32_t(j * n + i), v10 = v00 + 1, v01 = v00 + uint32_t(n), v11 = v01 + 1;
      mesh.indices.insert(mesh.indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  const double patch_size = 2.0 / patches_per_edge;
  for (int face = 0; face < 6; ++face) {
    for (int pj = 0; pj < patches_per_edge; ++pj) {
      for (int pi = 0; pi < patches_per_edge; ++pi) {
        MeshPatch patch;
        double s0 = -1.0 + pi * patch_size, t0 = -1.0 + pj * patch_size;
        patch.center_body = ellipsoid_point(
            shape, cube_to_sphere(face, s0 + 0.5 * patch_size, t0 + 0.5 * patch_size));
        for (int j = 0; j < n; ++j) {
          for (int i = 0; i < n; ++i) {
            double s = s0 + patch_size * i / quads_per_patch;
            double t = t0 + patch_size * j / quads_per_patch;
            glm::dvec3 p = ellipsoid_point(shape, cube_to_sphere(face, s, t));
            patch.offsets.emplace_back(p - patch.center_body);
            patch.normals.emplace_back(ellipsoid_normal(shape, p));
          }
        }
        mesh.patches.push_back(std::move(patch));
      }
    }
  }
  return mesh;
}

}  // namespace planet
