// The multiple-scattering LUT and the ground's sky irradiance as the sums
// of the orders computed by scattering_orders.comp, with their geometric
// tails (sum_of_orders in hillaire_functions.glsl).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_multiple_scattering;
layout(rgba32f, binding = 1) uniform writeonly image2D u_ground_irradiance;

layout(binding = 9) uniform sampler2D u_order_1;
layout(binding = 10) uniform sampler2D u_order_2;
layout(binding = 11) uniform sampler2D u_order_3;
layout(binding = 12) uniform sampler2D u_ground_1;
layout(binding = 13) uniform sampler2D u_ground_2;
layout(binding = 14) uniform sampler2D u_ground_3;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int n = kMultipleScatteringLutSize;
  if (texel.x >= n || texel.y > n) return;
  if (texel.y == n) {
    ivec2 g = ivec2(texel.x, 0);
    vec3 e = sum_of_orders(texelFetch(u_ground_1, g, 0).rgb, texelFetch(u_ground_2, g, 0).rgb,
                           texelFetch(u_ground_3, g, 0).rgb);
    imageStore(u_ground_irradiance, g, vec4(e, 1.0));
  } else {
    vec3 psi = sum_of_orders(texelFetch(u_order_1, texel, 0).rgb,
                             texelFetch(u_order_2, texel, 0).rgb,
                             texelFetch(u_order_3, texel, 0).rgb);
    imageStore(u_multiple_scattering, texel, vec4(psi, 1.0));
  }
}
