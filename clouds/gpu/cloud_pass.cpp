#include "clouds/gpu/cloud_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace planet {

std::array<float, 12> cloud_layer_uniforms(const shared::CloudLayer& l) {
  return {float(l.bottom_radius),
          float(l.top_radius),
          float(l.coverage),
          float(l.cumulus_share),
          float(l.weather_scale),
          float(l.shape_scale),
          float(l.erosion_scale),
          float(l.erosion),
          float(l.extinction),
          float(l.albedo),
          float(l.droplet_diameter_um),
          float(l.seed)};
}

CloudPass::CloudPass()
    : march_program_(
          Program::graphics("gl/shaders/fullscreen.vert", "clouds/gpu/clouds_march.frag")),
      upsample_program_(
          Program::graphics("gl/shaders/fullscreen.vert", "clouds/gpu/clouds_upsample.frag")),
      fill_program_(Program::graphics("gl/shaders/fullscreen.vert", "clouds/gpu/clouds_fill.frag")),
      blend_program_(
          Program::graphics("gl/shaders/fullscreen.vert", "clouds/gpu/clouds_blend.frag")) {}

void CloudPass::draw(const SkyFrame& frame, const shared::CloudLayer& layer,
                     const CloudQuality& quality, GLuint sky_irradiance) {
  const int factor = std::max(quality.downsample, 1);
  const int marched_width = (frame.width + factor - 1) / factor;
  const int marched_height = (frame.height + factor - 1) / factor;
  if (frame.width != width_ || frame.height != height_ || factor != downsample_) {
    width_ = frame.width;
    height_ = frame.height;
    downsample_ = factor;
    marched_ = make_texture_2d(GL_RGBA32F, marched_width, marched_height);
    marched_keys_ = make_texture_2d(GL_RG32F, marched_width, marched_height);
    marched_fbo_ = make_framebuffer({marched_.id(), marched_keys_.id()}, 0);
    full_ = make_texture_2d(GL_RGBA32F, width_, height_);
    full_fbo_ = make_framebuffer(full_.id(), 0);
  }
  // The march's inputs, for the marched pixels and for the full-resolution
  // ones that march themselves.
  auto set_march_uniforms = [&](const Program& program) {
    glUniform1i(program.uniform("u_has_sky_irradiance"), sky_irradiance != 0);
    glm::vec3 camera(frame.camera_atmo);
    glUniform3fv(program.uniform("u_camera"), 1, glm::value_ptr(camera));
    glUniformMatrix3fv(program.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                       glm::value_ptr(frame.atmo_ray_from_ndc));
    glUniform3fv(program.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
    glUniform1f(program.uniform("u_near"), frame.near);
    const std::array<float, 12> block = cloud_layer_uniforms(layer);
    glUniform4fv(program.uniform("u_layer"), 3, block.data());
    glUniform1i(program.uniform("u_steps"), quality.steps);
    glUniform1i(program.uniform("u_light_steps"), quality.light_steps);
    glUniform1i(program.uniform("u_octaves"), quality.octaves);
    glUniform2i(program.uniform("u_size"), frame.width, frame.height);
    glUniform1i(program.uniform("u_factor"), factor);
  };
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glBindTextureUnit(2, sky_irradiance);
  // The march discards the pixels whose rays meet no clouds: they keep the
  // clear's no clouds.
  const float no_clouds[4] = {0.0f, 0.0f, 0.0f, 1.0f}, no_layer[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(marched_fbo_.id(), GL_COLOR, 0, no_clouds);
  glClearNamedFramebufferfv(marched_fbo_.id(), GL_COLOR, 1, no_layer);
  pass_.begin(marched_fbo_.id(), marched_width, marched_height, march_program_);
  set_march_uniforms(march_program_);
  pass_.draw();
  glBindTextureUnit(3, marched_.id());
  glBindTextureUnit(4, marched_keys_.id());
  for (const Program* program : {&upsample_program_, &fill_program_}) {
    pass_.begin(full_fbo_.id(), width_, height_, *program);
    set_march_uniforms(*program);
    pass_.draw();
  }
  // out + T_clouds * behind: the clouds' rgb added, their alpha the
  // transmittance; the target's alpha kept.
  pass_.begin(frame.target_framebuffer, frame.width, frame.height, blend_program_);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
  glBindTextureUnit(0, full_.id());
  pass_.draw();
  glDisable(GL_BLEND);
}

}  // namespace planet
