#pragma once
// Where a sphere can appear on screen: a conservative rectangle in NDC
// that holds every pixel whose ray meets the sphere, for a sky pass that
// leaves the pixels outside the atmosphere's shell out.
#include <glm/glm.hpp>

#include <optional>

namespace planet {

struct NdcRect {
  glm::dvec2 min{-1.0}, max{1.0};
};

// The sphere at `center` (relative to the camera, in the frame of
// `ray_from_ndc`, which maps (ndc.x, ndc.y, 1) to a pixel's ray direction)
// of `radius`. The cone of rays that meet it projects to an ellipse; its
// bounding rectangle comes from the planes through the camera tangent to
// the cone (the dual of the cone's quadric). Nothing when the bound is not
// a finite rectangle: the camera inside the sphere, or the sphere reaching
// behind the camera's plane.
std::optional<NdcRect> sphere_ndc_bound(const glm::dvec3& center, double radius,
                                        const glm::dmat3& ray_from_ndc);

}  // namespace planet
