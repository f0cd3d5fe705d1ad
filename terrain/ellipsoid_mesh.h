#pragma once
// A smooth ellipsoid as cube-sphere patches: the first planet surface,
// until the quadtree terrain replaces it. Each patch keeps its vertices as
// float offsets from its own centre, which stays in double: the renderer
// subtracts the camera from the centre in double each frame, so no
// body-frame coordinate in double ever reaches the GPU.
#include "sim/body.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace planet {

struct MeshPatch {
  glm::dvec3 center_body{0.0};
  std::vector<glm::vec3> offsets;  // vertex - center_body
  std::vector<glm::vec3> normals;  // ellipsoid normals, unit
};

struct PatchMesh {
  std::vector<MeshPatch> patches;
  std::vector<uint32_t> indices;  // one triangle list shared by every patch
};

// The unit-cube face point (face 0..5, s and t in [-1, 1]) to a unit
// direction, through the tangent warp tan(pi/4 s) that evens out cell sizes.
glm::dvec3 cube_to_sphere(int face, double s, double t);

// The point of the ellipsoid in geocentric direction `dir`.
glm::dvec3 ellipsoid_point(const Ellipsoid& shape, const glm::dvec3& dir);
glm::dvec3 ellipsoid_normal(const Ellipsoid& shape, const glm::dvec3& point);

// 6 faces x patches_per_edge^2 patches, each a grid of quads_per_patch^2 quads.
PatchMesh make_ellipsoid_mesh(const Ellipsoid& shape, int patches_per_edge, int quads_per_patch);

}  // namespace planet
