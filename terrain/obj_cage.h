#pragma once
// A subdivision control cage read from a Wavefront OBJ file: vertex
// positions ("v") and polygon faces ("f", any of the v, v/vt, v//vn and
// v/vt/vn forms, negative indices counting back from the last vertex).
// Everything else (normals, texture coordinates, groups, materials) is
// ignored. Vertices at exactly the same position are merged, since shape
// models often repeat a vertex along a texture seam, which would otherwise
// open the cage there.
#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

namespace planet {

struct ObjCage {
  std::vector<glm::dvec3> vertices;
  std::vector<int> face_sizes;    // vertices per face
  std::vector<int> face_indices;  // all faces' vertex indices, in order
};

// Throws InputError naming the file (and line, where one is at fault) when
// the file cannot be read, holds no face, has a vertex that is not finite
// or an index out of range, or is not a closed, consistently oriented
// manifold: every edge must be shared by exactly two faces, which run
// along it in opposite directions.
ObjCage read_obj_cage(const std::filesystem::path& file);

}  // namespace planet
