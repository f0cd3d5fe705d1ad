// Hillaire 2020, sec. 5.5: Psi_ms = L_2 / (1 - f_ms) per (mu_s, altitude),
// one invocation per texel integrating its 64 directions.
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_output;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= kMultipleScatteringLutWidth || texel.y >= kMultipleScatteringLutHeight) return;
  Atmosphere atmosphere = block_atmosphere();
  float u = (float(texel.x) + 0.5) / float(kMultipleScatteringLutWidth);
  float v = (float(texel.y) + 0.5) / float(kMultipleScatteringLutHeight);
  float r, mu_s;
  multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, v, r, mu_s);
  imageStore(u_output, texel, vec4(multiple_scattering_texel(atmosphere, r, mu_s), 1.0));
}
