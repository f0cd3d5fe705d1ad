// Bruneton 2017, "Ground irradiance": the sun's irradiance on horizontal
// ground at (r, mu_s), the start of the irradiance's orders (the technique
// keeps the sky's alone: the sun's is evaluated exactly at render time).
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_transmittance;
layout(rgba32f, binding = 0) uniform writeonly image2D u_delta_irradiance;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= IRRADIANCE_WIDTH || texel.y >= IRRADIANCE_HEIGHT) return;
  Atmosphere atmosphere = block_atmosphere();
  float r, mu_s;
  bruneton_r_mu_s_from_irradiance_uv(
      atmosphere, (vec2(texel) + 0.5) / vec2(IRRADIANCE_WIDTH, IRRADIANCE_HEIGHT), r, mu_s);
  imageStore(u_delta_irradiance, texel,
             vec4(bruneton_direct_irradiance(atmosphere, u_transmittance, r, mu_s), 1.0));
}
