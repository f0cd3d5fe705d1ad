#include "atmosphere/gpu/atmosphere_block.h"

namespace planet {

AtmosphereBlock make_atmosphere_block(const AtmosphereModel& m) {
  AtmosphereBlock b{};
  b.radii = glm::vec4(float(m.bottom_radius), float(m.top_radius), float(m.mie_g),
                      float(m.sun_angular_radius));
  b.solar_irradiance = glm::vec4(glm::vec3(m.solar_irradiance), 0.0f);
  b.rayleigh_scattering = glm::vec4(glm::vec3(m.rayleigh.scattering), 0.0f);
  b.mie_scattering = glm::vec4(glm::vec3(m.mie.scattering), 0.0f);
  b.mie_extinction = glm::vec4(glm::vec3(m.mie.extinction()), 0.0f);
  b.absorption_extinction = glm::vec4(glm::vec3(m.absorber.extinction()), 0.0f);
  // w: the Mie phase function, 0 Cornette-Shanks, 1 Henyey-Greenstein.
  b.ground_albedo = glm::vec4(glm::vec3(m.ground_albedo), float(int(m.mie_phase)));
  const DensityProfile* profiles[3] = {&m.rayleigh.density, &m.mie.density, &m.absorber.density};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 2; ++k) {
      const DensityLayer& l = profiles[i]->layers[size_t(k)];
      b.layer_a[2 * i + k] = glm::vec4(float(l.width), float(l.exp_term), float(l.exp_scale),
                                       float(l.linear_term));
      b.layer_b[2 * i + k] = glm::vec4(float(l.constant_term), 0.0f, 0.0f, 0.0f);
    }
  }
  return b;
}

}  // namespace planet
