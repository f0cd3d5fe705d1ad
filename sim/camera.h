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

}  // namespace planet
