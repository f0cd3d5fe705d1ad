// The sky irradiance's orders past the last one, as geometric_tail.comp
// does for the scattering: the last order's irradiance times q / (1 - q).
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 1) uniform sampler2D u_before_last;
layout(binding = 2) uniform sampler2D u_last;
layout(rgba32f, binding = 1) uniform image2D u_irradiance;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= IRRADIANCE_WIDTH || texel.y >= IRRADIANCE_HEIGHT) return;
  vec3 before = texelFetch(u_before_last, texel, 0).rgb;
  vec3 last = texelFetch(u_last, texel, 0).rgb;
  vec3 q = clamp(last / max(before, vec3(1e-30)), vec3(0.0), vec3(0.5));
  imageStore(u_irradiance, texel, imageLoad(u_irradiance, texel) + vec4(last * q / (1.0 - q), 0.0));
}
