// Hillaire 2020, sec. 5.1: transmittance to the top of the atmosphere over
// (r, mu) in Bruneton's mapping, kTransmittanceSteps trapezoids per texel;
// alpha holds the Mie density's column over the same path, for the
// forward gain (hillaire_functions.glsl).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_output;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= kTransmittanceLutWidth || texel.y >= kTransmittanceLutHeight) return;
  Atmosphere atmosphere = block_atmosphere();
  float u = (float(texel.x) + 0.5) / float(kTransmittanceLutWidth);
  float v = (float(texel.y) + 0.5) / float(kTransmittanceLutHeight);
  float r, mu;
  transmittance_lut_r_mu_from_uv(atmosphere, u, v, r, mu);
  vec3 transmittance = transmittance_to_top(atmosphere, r, mu, kTransmittanceSteps);
  float mie_column = mie_column_to_top(atmosphere, r, mu, kTransmittanceSteps);
  imageStore(u_output, texel, vec4(transmittance, mie_column));
}
