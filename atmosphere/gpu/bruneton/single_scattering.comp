// Bruneton 2017, "Single scattering": Rayleigh and Mie scattered once, per
// texel of the 4D table, without their phase functions. Writes the order's
// two tables (for the next orders), and the tables the sky is drawn from:
// the scattering (Rayleigh, and with COMBINED Mie's red in alpha) and, apart,
// single Mie.
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_transmittance;
layout(rgba32f, binding = 0) uniform writeonly image3D u_delta_rayleigh;
layout(rgba32f, binding = 1) uniform writeonly image3D u_delta_mie;
layout(SCATTERING_FORMAT, binding = 2) uniform writeonly image3D u_scattering;
#ifndef COMBINED
layout(SCATTERING_FORMAT, binding = 3) uniform writeonly image3D u_single_mie;
#endif

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID.xy, u_first_layer + int(gl_GlobalInvocationID.z));
  if (any(greaterThanEqual(texel, scattering_extent()))) return;
  Atmosphere atmosphere = block_atmosphere();
  float r, mu, mu_s, nu;
  bool ground;
  bruneton_r_mu_mu_s_nu_from_texel(atmosphere, vec3(texel), r, mu, mu_s, nu, ground);
  vec3 rayleigh, mie;
  bruneton_single_scattering(atmosphere, u_transmittance, r, mu, mu_s, nu, ground,
                             INTEGRATION_STEPS, rayleigh, mie);
  imageStore(u_delta_rayleigh, texel, vec4(rayleigh, 1.0));
  imageStore(u_delta_mie, texel, vec4(mie, 1.0));
#ifdef COMBINED
  imageStore(u_scattering, texel, vec4(rayleigh, mie.r));
#else
  imageStore(u_scattering, texel, vec4(rayleigh, 1.0));
  imageStore(u_single_mie, texel, vec4(mie, 1.0));
#endif
}
