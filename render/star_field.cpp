#include "render/star_field.h"

#include "gl/context.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace planet {

double star_radiance_per_sun(double magnitude) {
  // One arcminute, the eye's resolution: a star is a disc that wide to it.
  const double radius = 0.5 * glm::radians(1.0 / 60.0);
  return star_irradiance_per_sun(magnitude) / (glm::pi<double>() * radius * radius);
}

StarField::StarField(const std::vector<Star>& stars)
    : program_(Program::graphics("render/shaders/stars.vert", "render/shaders/stars.frag")),
      count_(int(stars.size())) {
  // Per star: its ICRF direction and its radiance per unit solar
  // irradiance.
  std::vector<glm::vec4> data;
  data.reserve(stars.size());
  for (const Star& s : stars) {
    data.emplace_back(glm::vec3(s.dir_icrf), float(star_radiance_per_sun(s.magnitude)));
  }
  vertices_ = make_buffer(data.size() * sizeof(glm::vec4), data.data(), 0);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  vao_ = VertexArray(vao);
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(glm::vec4));
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  check_gl_errors("StarField setup");
}

void StarField::draw(GLuint target, int width, int height, GLuint depth, const Camera& camera,
                     const StarView& view) const {
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_PROGRAM_POINT_SIZE);
  glPointSize(1.0f);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
  glUseProgram(program_.id());
  // Rotations only: directions need no position, and float holds them.
  const glm::dmat3 view_from_body = glm::mat3_cast(glm::conjugate(camera.body_from_camera));
  const glm::mat3 view_from_icrf(view_from_body * view.body_from_icrf);
  const glm::mat3 body_from_icrf(view.body_from_icrf);
  const glm::mat4 clip =
      clip_from_view_reversed_z(camera.vertical_fov, double(width) / height, camera.near);
  glUniformMatrix3fv(program_.uniform("u_view_from_icrf"), 1, GL_FALSE,
                     glm::value_ptr(view_from_icrf));
  glUniformMatrix3fv(program_.uniform("u_body_from_icrf"), 1, GL_FALSE,
                     glm::value_ptr(body_from_icrf));
  glUniformMatrix4fv(program_.uniform("u_clip_from_view"), 1, GL_FALSE, glm::value_ptr(clip));
  glUniform3fv(program_.uniform("u_sun_at_1au"), 1, glm::value_ptr(view.sun_at_1au));
  glUniform1f(program_.uniform("u_scale"), view.scale);
  glUniform1i(program_.uniform("u_has_atmosphere"), view.has_atmosphere ? 1 : 0);
  glUniform3fv(program_.uniform("u_atmo_scale"), 1, glm::value_ptr(glm::vec3(view.atmo_scale)));
  glUniform3fv(program_.uniform("u_camera_atmo"), 1,
               glm::value_ptr(glm::vec3(view.atmo_scale * camera.pos_body)));
  glUniform1i(program_.uniform("u_has_clouds"), view.clouds != 0 ? 1 : 0);
  glBindTextureUnit(0, depth);
  glBindTextureUnit(1, view.clouds);
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, count_);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
}

}  // namespace planet
