// The multiple-scattering LUT (mean and moment, side by side) and the
// ground's sky irradiance as the sums of the orders that
// scattering_orders.comp computed, with their geometric tails
// (sum_of_orders in hillaire_functions.glsl).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_multiple_scattering;
layout(rgba32f, binding = 1) uniform writeonly image2D u_ground_irradiance;

layout(binding = 9) uniform sampler2D u_order_1;
layout(binding = 10) uniform sampler2D u_order_2;
layout(binding = 11) uniform sampler2D u_order_3;

vec3 summed(ivec2 texel, ivec2 mean_texel) {
  return sum_of_orders(texelFetch(u_order_2, mean_texel, 0).rgb,
                       texelFetch(u_order_3, mean_texel, 0).rgb,
                       texelFetch(u_order_1, texel, 0).rgb, texelFetch(u_order_2, texel, 0).rgb,
                       texelFetch(u_order_3, texel, 0).rgb);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int n = kMultipleScatteringLutSize;
  if (texel.x >= n || texel.y > n) return;
  if (texel.y == n) {
    imageStore(u_ground_irradiance, ivec2(texel.x, 0), vec4(summed(texel, texel), 1.0));
  } else {
    for (int part = 0; part < kFieldParts; ++part) {
      ivec2 t = texel + ivec2(part * n, 0);
      imageStore(u_multiple_scattering, t, vec4(summed(t, texel), 1.0));
    }
  }
}
