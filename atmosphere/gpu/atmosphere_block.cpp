#include "atmosphere/gpu/atmosphere_block.h"

#include "atmosphere/math/shared_math.h"

namespace planet {

// The shared Atmosphere in float, four to a vec4: what the model makes
// (shared::to_shared, the one place that derives the extinctions and the
// phase function's flag) is packed here and unpacked by block_atmosphere()
// in atmosphere_block.glsl, field for field.
AtmosphereBlock make_atmosphere_block(const AtmosphereModel& model) {
  const shared::Atmosphere a = shared::to_shared(model);
  AtmosphereBlock b{};
  b.radii = glm::vec4(float(a.bottom_radius), float(a.top_radius), float(a.mie_g),
                      float(a.sun_angular_radius));
  b.solar_irradiance = glm::vec4(glm::vec3(a.solar_irradiance), 0.0f);
  b.rayleigh_scattering = glm::vec4(glm::vec3(a.rayleigh_scattering), 0.0f);
  b.mie_scattering = glm::vec4(glm::vec3(a.mie_scattering), 0.0f);
  b.mie_extinction = glm::vec4(glm::vec3(a.mie_extinction), 0.0f);
  b.absorption_extinction = glm::vec4(glm::vec3(a.absorption_extinction), 0.0f);
  b.ground_albedo = glm::vec4(glm::vec3(a.ground_albedo), float(a.mie_phase_hg));
  const DensityProfile* profiles[3] = {&a.rayleigh_density, &a.mie_density, &a.absorption_density};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 2; ++k) {
      const DensityLayer& l = profiles[i]->layers[size_t(k)];
      b.layer_a[2 * i + k] =
          glm::vec4(float(l.width), float(l.exp_term), float(l.exp_scale), float(l.linear_term));
      b.layer_b[2 * i + k] = glm::vec4(float(l.constant_term), 0.0f, 0.0f, 0.0f);
    }
  }
  return b;
}

}  // namespace planet
