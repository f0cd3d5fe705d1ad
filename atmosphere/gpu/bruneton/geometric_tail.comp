// The orders past the last one iterated, as a geometric series (as the
// hillaire technique sums its own, Hillaire 2020 eq. 9): each texel's last
// order times q / (1 - q), q the ratio of its last two orders per channel;
// added to the sky's scattering (without Rayleigh's phase, as
// multiple_scattering.comp adds an order). Bruneton stops at the last
// order, which left the blue of a noon sky 2.6 % dark after four (3.4 %
// relative RMSE; with the tail 1.6 %). q is held below 0.5: in thick dust
// the ratio of successive orders still falls after the fourth, and a tail
// from it overshoots (Mars sunset, red: 102 % with q up to 0.9, 17 % with
// 0.5, 38 % with no tail).
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 1) uniform sampler3D u_before_last;
layout(binding = 2) uniform sampler3D u_last;
layout(SCATTERING_FORMAT, binding = 1) uniform image3D u_scattering;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID.xy, u_first_layer + int(gl_GlobalInvocationID.z));
  if (any(greaterThanEqual(texel, scattering_extent()))) return;
  Atmosphere atmosphere = block_atmosphere();
  float r, mu, mu_s, nu;
  bool ground;
  bruneton_r_mu_mu_s_nu_from_texel(atmosphere, vec3(texel), r, mu, mu_s, nu, ground);
  vec3 before = texelFetch(u_before_last, texel, 0).rgb;
  vec3 last = texelFetch(u_last, texel, 0).rgb;
  vec3 q = clamp(last / max(before, vec3(1e-30)), vec3(0.0), vec3(0.5));
  vec4 sum = imageLoad(u_scattering, texel);
  imageStore(u_scattering, texel, vec4(sum.rgb + last * q / (1.0 - q) / rayleigh_phase(nu), sum.a));
}
