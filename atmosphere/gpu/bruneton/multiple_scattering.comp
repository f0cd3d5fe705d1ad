// Bruneton 2017, "Multiple scattering": the light of order n arriving along
// every texel's ray, the density of order n integrated with its
// transmittance to the nearest boundary. Writes the order's table, and adds
// it to the scattering the sky is drawn from, divided by Rayleigh's phase
// function (which the sky pass multiplies back: the table holds Rayleigh and
// the orders above the first without their phase).
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_transmittance;
layout(binding = 1) uniform sampler3D u_density;
layout(rgba32f, binding = 0) uniform writeonly image3D u_delta_multiple;
layout(SCATTERING_FORMAT, binding = 1) uniform image3D u_scattering;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID.xy, u_first_layer + int(gl_GlobalInvocationID.z));
  if (any(greaterThanEqual(texel, scattering_extent()))) return;
  Atmosphere atmosphere = block_atmosphere();
  float r, mu, mu_s, nu;
  bool ground;
  bruneton_r_mu_mu_s_nu_from_texel(atmosphere, vec3(texel), r, mu, mu_s, nu, ground);
  vec3 radiance = bruneton_multiple_scattering(atmosphere, u_transmittance, u_density, r, mu, mu_s,
                                               nu, ground, INTEGRATION_STEPS);
  imageStore(u_delta_multiple, texel, vec4(radiance, 1.0));
  vec4 sum = imageLoad(u_scattering, texel);
  imageStore(u_scattering, texel, vec4(sum.rgb + radiance / rayleigh_phase(nu), sum.a));
}
