// The forward-gain LUT (see "The sun's glow past the table's degree" in
// hillaire_functions.glsl): exp(-tau) forward_gain over (nu, tau) for the
// model's Mie g.
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform writeonly image2D u_output;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= kForwardGainLutWidth || texel.y >= kForwardGainLutHeight) return;
  Atmosphere atmosphere = block_atmosphere();
  float nu, tau;
  forward_gain_lut_nu_tau_from_uv((float(texel.x) + 0.5) / float(kForwardGainLutWidth),
                                  (float(texel.y) + 0.5) / float(kForwardGainLutHeight), nu, tau);
  float gain = forward_gain_times_extinction(atmosphere.mie_g, atmosphere.mie_phase_hg, nu, tau);
  imageStore(u_output, texel, vec4(gain, 0.0, 0.0, 1.0));
}
