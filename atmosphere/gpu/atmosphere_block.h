#pragma once
// C++ mirror of the std140 block in atmosphere/shaders/atmosphere_block.glsl:
// the shared Atmosphere (atmosphere/shaders/definitions.glsl) in float,
// packed four to a vec4.
#include "atmosphere/model.h"

#include <glm/glm.hpp>

#include <cstddef>

namespace planet {

struct AtmosphereBlock {
  glm::vec4 radii;  // bottom, top, mie g, sun angular radius
  glm::vec4 solar_irradiance;
  glm::vec4 rayleigh_scattering;
  glm::vec4 mie_scattering;
  glm::vec4 mie_extinction;
  glm::vec4 absorption_extinction;
  glm::vec4 ground_albedo;  // w: the Mie phase function (MiePhase)
  glm::vec4 layer_a[6];
  glm::vec4 layer_b[6];
};
static_assert(sizeof(AtmosphereBlock) == 19 * 16, "std140: 19 vec4");
static_assert(offsetof(AtmosphereBlock, layer_a) == 7 * 16);
static_assert(offsetof(AtmosphereBlock, layer_b) == 13 * 16);

// Binding point of the block in every shader that includes it.
constexpr unsigned kAtmosphereBlockBinding = 0;

// The model's one way onto the GPU: shared::to_shared packed, which
// block_atmosphere() in the shaders unpacks field for field.
AtmosphereBlock make_atmosphere_block(const AtmosphereModel& model);

}  // namespace planet
