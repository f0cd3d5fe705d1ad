#include "clouds/gpu/cloud_pass.h"

#include <glm/gtc/type_ptr.hpp>

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
    : program_(Program::graphics("gl/shaders/fullscreen.vert", "clouds/gpu/clouds.frag")) {}

void CloudPass::draw(const SkyFrame& frame, const shared::CloudLayer& layer,
                     const CloudQuality& quality, GLuint sky_irradiance) const {
  pass_.begin(frame.target_framebuffer, frame.width, frame.height, program_);
  glDisable(GL_STENCIL_TEST);
  // out + T_clouds * behind: the shader's rgb added, its alpha the clouds'
  // transmittance; the target's alpha kept.
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glBindTextureUnit(2, sky_irradiance);
  glUniform1i(program_.uniform("u_has_sky_irradiance"), sky_irradiance != 0);
  glm::vec3 camera(frame.camera_atmo);
  glUniform3fv(program_.uniform("u_camera"), 1, glm::value_ptr(camera));
  glUniformMatrix3fv(program_.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(program_.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform1f(program_.uniform("u_near"), frame.near);
  const std::array<float, 12> block = cloud_layer_uniforms(layer);
  glUniform4fv(program_.uniform("u_layer"), 3, block.data());
  glUniform1i(program_.uniform("u_steps"), quality.steps);
  glUniform1i(program_.uniform("u_light_steps"), quality.light_steps);
  glUniform1i(program_.uniform("u_octaves"), quality.octaves);
  pass_.draw();
  glDisable(GL_BLEND);
}

}  // namespace planet
