// Bruneton 2017, "Transmittance": the optical depth (bruneton_functions.glsl
// says why not its exponential) to the top of the atmosphere over (r, mu)
// in the shared mapping (transmittance.glsl), by the shared quadrature with
// TRANSMITTANCE_STEPS samples crowded toward the start.
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_output;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= TRANSMITTANCE_WIDTH || texel.y >= TRANSMITTANCE_HEIGHT) return;
  Atmosphere atmosphere = block_atmosphere();
  vec2 size = vec2(TRANSMITTANCE_WIDTH, TRANSMITTANCE_HEIGHT);
  vec2 r_mu = transmittance_r_mu_from_uv(atmosphere, (vec2(texel) + 0.5) / size, size);
  imageStore(u_output, texel,
             vec4(optical_depth_to_top(atmosphere, r_mu.x, r_mu.y, TRANSMITTANCE_STEPS), 1.0));
}
