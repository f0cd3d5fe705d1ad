#include "sim/camera.h"

#include <cmath>

namespace planet {

glm::mat4 clip_from_view_reversed_z(double vertical_fov, double aspect, double near) {
  double f = 1.0 / std::tan(0.5 * vertical_fov);
  glm::mat4 m(0.0f);
  m[0][0] = float(f / aspect);
  m[1][1] = float(f);
  m[3][2] = float(near);  // z_clip = near
  m[2][3] = -1.0f;        // w_clip = -z_view
  return m;
}

glm::dmat3 view_ray_from_ndc(double vertical_fov, double aspect) {
  double tan_half = std::tan(0.5 * vertical_fov);
  return glm::dmat3(glm::dvec3(tan_half * aspect, 0, 0), glm::dvec3(0, tan_half, 0),
                    glm::dvec3(0, 0, -1));
}

}  // namespace planet
