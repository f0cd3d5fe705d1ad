#include "atmosphere/gpu/terrain_shadow.h"

#include <glm/gtc/type_ptr.hpp>

namespace planet {

void bind_terrain_shadow(const Program& program, const SkyTerrainShadow& shadow) {
  const bool on = shadow.active();
  glBindTextureUnit(kTerrainShadowUnit, on ? shadow.texture : 0);
  glUniform3fv(program.uniform("u_shadow_up"), 1, glm::value_ptr(shadow.up));
  glUniform3fv(program.uniform("u_shadow_east"), 1, glm::value_ptr(shadow.east));
  glUniform3fv(program.uniform("u_shadow_north"), 1, glm::value_ptr(shadow.north));
  glUniform2f(program.uniform("u_shadow_plane"), shadow.bottom_radius,
              on ? shadow.half_side : 1.0f);
  glUniform1f(program.uniform("u_shadow_strength"), on ? shadow.strength : 0.0f);
  glUniform1f(program.uniform("u_shadow_softness"), kTerrainShadowSoftness);
}

}  // namespace planet
