// What every pass of the bruneton technique shares: the model's block, the
// tables' types and sizes (set as defines by the technique from its
// quality), and Bruneton's functions (atmosphere/shaders/
// bruneton_functions.glsl).
#include "atmosphere/shaders/atmosphere_block.glsl"

#define Real4 vec4
#define Table2D sampler2D
#define Table3D sampler3D

// The smallest sun zenith cosine the tables cover, from the model's shell
// (bruneton_technique.cpp).
uniform float u_mu_s_min;

#include "atmosphere/shaders/bruneton_functions.glsl"

BrunetonSizes bruneton_sizes() {
  return BrunetonSizes(TRANSMITTANCE_WIDTH, TRANSMITTANCE_HEIGHT, IRRADIANCE_WIDTH,
                       IRRADIANCE_HEIGHT, SCATTERING_R, SCATTERING_MU, SCATTERING_MU_S,
                       SCATTERING_NU, u_mu_s_min);
}

// The 3D tables' extent in texels: (nu mu_s) x mu x r.
ivec3 scattering_extent() {
  return ivec3(SCATTERING_NU * SCATTERING_MU_S, SCATTERING_MU, SCATTERING_R);
}

// The passes over a 3D table run a slice of its r layers at a time, from
// u_first_layer (so that a long precompute shows its progress).
uniform int u_first_layer;
