#include "atmosphere/gpu/raymarch/raymarch_technique.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "atmosphere/gpu/terrain_shadow.h"
#include "gl/timer.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

namespace planet {

namespace {

std::vector<std::string> raymarch_defines(const RaymarchTechnique::Steps& steps) {
  std::vector<std::string> defines = {fmt::format("VIEW_STEPS {}", steps.view),
                                      fmt::format("LIGHT_STEPS {}", steps.light)};
  if (steps.terrain_shadows) defines.push_back("TERRAIN_SHADOWS 1");
  return defines;
}

}  // namespace

RaymarchTechnique::RaymarchTechnique(Steps steps)
    : steps_(steps),
      program_(Program::graphics("gl/shaders/fullscreen.vert",
                                 "atmosphere/gpu/raymarch/raymarch_sky.frag",
                                 raymarch_defines(steps))),
      block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {}

void RaymarchTechnique::update(const AtmosphereModel& model) {
  AtmosphereBlock block = make_atmosphere_block(model);
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
}

void RaymarchTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  std::vector<Pass> passes;
  passes.push_back({.name = "sky", .run = [this, &frame] { draw_sky(frame); }});
  graph_.run(std::move(passes), timer);
}

void RaymarchTechnique::draw_sky(const SkyFrame& frame) {
  pass_.begin(frame.target_framebuffer, frame.width, frame.height, program_);
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glBindTextureUnit(SkyFrame::kGroundBelowUnit, frame.ground_below_texture);
  glm::vec3 camera(frame.camera_atmo);
  glUniform3fv(program_.uniform("u_camera"), 1, glm::value_ptr(camera));
  glUniformMatrix3fv(program_.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(program_.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform4f(program_.uniform("u_moon"), frame.moon_centre_atmo.x, frame.moon_centre_atmo.y,
              frame.moon_centre_atmo.z, frame.moon_radius);
  glUniform1f(program_.uniform("u_near"), frame.near);
  glUniform2f(program_.uniform("u_viewport"), float(frame.width), float(frame.height));
  if (steps_.terrain_shadows) bind_terrain_shadow(program_, frame.terrain_shadow);
  pass_.draw();
}

}  // namespace planet
