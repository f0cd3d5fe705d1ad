#include "atmosphere/gpu/raymarch/raymarch_technique.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "render/gl/timer.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

namespace planet {

RaymarchTechnique::RaymarchTechnique(Steps steps)
    : steps_(steps),
      program_(Program::graphics("render/shaders/fullscreen.vert",
                                 "atmosphere/gpu/raymarch/raymarch_sky.frag",
                                 {fmt::format("VIEW_STEPS {}", steps.view),
                                  fmt::format("LIGHT_STEPS {}", steps.light)})),
      block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  empty_vao_ = VertexArray(vao);
}

void RaymarchTechnique::update(const AtmosphereModel& model) {
  AtmosphereBlock block = make_atmosphere_block(model);
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
}

void RaymarchTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  timer.begin("sky");
  glBindFramebuffer(GL_FRAMEBUFFER, frame.target_framebuffer);
  glViewport(0, 0, frame.width, frame.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glm::vec3 camera(frame.camera_atmo);
  glUniform3fv(program_.uniform("u_camera"), 1, glm::value_ptr(camera));
  glUniformMatrix3fv(program_.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(program_.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform1f(program_.uniform("u_near"), frame.near);
  glUniform2f(program_.uniform("u_viewport"), float(frame.width), float(frame.height));
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  timer.end();
}

}  // namespace planet
