// The multiple-scattering LUT (its kFieldParts terms side by side) and the
// ground's sky irradiance as the sums of the orders that
// scattering_orders.comp computed, with their geometric tails
// (with_geometric_tail in hillaire_functions.glsl).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_multiple_scattering;
layout(rgba32f, binding = 1) uniform writeonly image2D u_ground_irradiance;

layout(binding = 9) uniform sampler2D u_orders[kScatteringOrders];

vec3 summed(ivec2 texel, ivec2 mean_texel) {
  vec3 sum = vec3(0.0);
  for (int k = 0; k < kScatteringOrders; ++k) sum += texelFetch(u_orders[k], texel, 0).rgb;
  return with_geometric_tail(texelFetch(u_orders[kScatteringOrders - 2], mean_texel, 0).rgb,
                             texelFetch(u_orders[kScatteringOrders - 1], mean_texel, 0).rgb, sum,
                             texelFetch(u_orders[kScatteringOrders - 1], texel, 0).rgb);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int w = kMultipleScatteringLutWidth, h = kMultipleScatteringLutHeight;
  if (texel.x >= w || texel.y > h) return;
  if (texel.y == h) {
    imageStore(u_ground_irradiance, ivec2(texel.x, 0), vec4(summed(texel, texel), 1.0));
  } else {
    for (int part = 0; part < kFieldParts; ++part) {
      ivec2 t = texel + ivec2(part * w, 0);
      imageStore(u_multiple_scattering, t, vec4(summed(t, texel), 1.0));
    }
  }
}
