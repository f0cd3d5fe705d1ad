// The multiple-scattering LUT (its kFieldParts terms side by side) and the
// ground's sky irradiance as the sums of the orders that
// scattering_orders.comp computed, with their geometric tails
// (with_geometric_tail in hillaire_functions.glsl).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_multiple_scattering;
layout(rgba32f, binding = 1) uniform writeonly image2D u_ground_irradiance;

layout(binding = 9) uniform sampler2D u_orders[kScatteringOrders];

const int kLutWidth = kMultipleScatteringLutWidth, kLutHeight = kMultipleScatteringLutHeight;

// Part `part` of order k + 1 at the LUT's texel (row kLutHeight: the
// ground's irradiance): the texel itself where the order has the LUT's
// grid; on a coarser one, bilinear between its four nearest texels (the
// ground's row, between two), clamped to the edge as GL samples, in full
// float precision.
vec3 order_at(int k, int part, ivec2 texel) {
  int w = scattering_order_width(k + 1), h = scattering_order_height(k + 1);
  if (w == kLutWidth && h == kLutHeight) {
    return texelFetch(u_orders[k], texel + ivec2(part * w, 0), 0).rgb;
  }
  float u = regrid_texture_coord((float(texel.x) + 0.5) / float(kLutWidth), kLutWidth, w);
  float x = clamp(u * float(w) - 0.5, 0.0, float(w - 1));
  int x0 = int(x), x1 = min(x0 + 1, w - 1);
  float y = float(h);
  if (texel.y < kLutHeight) {
    float v = regrid_texture_coord((float(texel.y) + 0.5) / float(kLutHeight), kLutHeight, h);
    y = clamp(v * float(h) - 0.5, 0.0, float(h - 1));
  }
  int y0 = int(y), y1 = texel.y < kLutHeight ? min(y0 + 1, h - 1) : y0;
  int offset = part * w;
  vec3 low = mix(texelFetch(u_orders[k], ivec2(offset + x0, y0), 0).rgb,
                 texelFetch(u_orders[k], ivec2(offset + x1, y0), 0).rgb, x - float(x0));
  vec3 high = mix(texelFetch(u_orders[k], ivec2(offset + x0, y1), 0).rgb,
                  texelFetch(u_orders[k], ivec2(offset + x1, y1), 0).rgb, x - float(x0));
  return mix(low, high, y - float(y0));
}

vec3 summed(int part, ivec2 texel) {
  vec3 sum = vec3(0.0);
  for (int k = 0; k < kScatteringOrders; ++k) sum += order_at(k, part, texel);
  return with_geometric_tail(order_at(kScatteringOrders - 2, kFieldMean, texel),
                             order_at(kScatteringOrders - 1, kFieldMean, texel), sum,
                             order_at(kScatteringOrders - 1, part, texel));
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= kLutWidth || texel.y > kLutHeight) return;
  if (texel.y == kLutHeight) {
    imageStore(u_ground_irradiance, ivec2(texel.x, 0), vec4(summed(kFieldMean, texel), 1.0));
  } else {
    for (int part = 0; part < kFieldParts; ++part) {
      imageStore(u_multiple_scattering, texel + ivec2(part * kLutWidth, 0),
                 vec4(summed(part, texel), 1.0));
    }
  }
}
