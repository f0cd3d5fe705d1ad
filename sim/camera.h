#pragma once
// The camera as the simulation hands it to the renderer: a pose in double in
// the body-fixed frame and a perspective.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace planet {

struct Camera {
  glm::dvec3 pos_body{0.0};
  // Maps camera axes (x right, y up, looking along -z) into body axes.
  glm::dquat body_from_camera{1.0, 0.0, 0.0, 0.0};
  double vertical_fov = glm::radians(60.0);
  // Nearest distance drawn; with reversed-Z and an infinite far plane this is
  // the only depth parameter.
  double near = 0.1;

  glm::dvec3 forward_body() const { return body_from_camera * glm::dvec3(0, 0, -1); }
};

// Perspective with reversed Z and an infinite far plane: depth = near / view
// depth, so 1 at the near plane and 0 at infinity (Upchurch and Desbrun
// 2012; Reed 2015 on why float depth wants it this way round).
glm::mat4 clip_from_view_reversed_z(double vertical_fov, double aspect, double near);

// Maps (ndc.x, ndc.y, 1) to the unnormalised view-space direction of the
// pixel, (x tan aspect, y tan, -1) with tan that of half the vertical
// field: its length is the distance along the ray per unit of view depth.
glm::dmat3 view_ray_from_ndc(double vertical_fov, double aspect);

}  // namespace planet
