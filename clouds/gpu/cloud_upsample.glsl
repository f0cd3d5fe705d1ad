// The marched clouds at full resolution: each pixel blends the four
// marched pixels around it (bilinearly, by where their source pixels lie)
// whose marches are like its own (clouds_upsample.frag), and marches
// itself where none does (clouds_fill.frag), so that clouds neither bleed
// across a silhouette (a mountain against the sky, the planet's limb) nor
// leave a hole beside one.
#include "clouds/gpu/cloud_march.glsl"

layout(binding = 3) uniform sampler2D u_marched;

layout(binding = 4) uniform sampler2D u_marched_keys;  // cloud_ray_key of each

// Full-resolution pixel `pixel`'s cloud_ray_key.
vec2 cloud_march_key(ivec2 pixel) {
  CloudRay ray;
  return cloud_ray(pixel, ray) ? cloud_ray_key(ray) : vec2(0.0);
}

// Whether two pixels' marches are alike: neither meets the layer, or both
// cross it over lengths within 10 % of each other (the way through the
// layer changes fast toward the limb, where a ray grazes it) and end alike:
// both in the open sky, both on surfaces under the layer, or on surfaces
// in or above it within 10 % of each other's distance (neighbours on a
// surface that recedes smoothly differ by less: 5 % on level ground seen
// 10 degrees down, two pixels apart at 480x270 and 70 degrees of view).
bool cloud_same_march(vec2 key, vec2 other) {
  if (key.x == 0.0 || other.x == 0.0) return key.x == other.x;
  if (abs(other.x - key.x) > 0.1 * max(key.x, other.x)) return false;
  if (key.y <= 0.0 || other.y <= 0.0) return key.y == other.y;
  return abs(other.y - key.y) <= 0.1 * key.y;
}

// Blends the marched pixels whose marches are like this one's, bilinearly by
// where their sources lie; -1 where none does.
vec4 cloud_upsampled(ivec2 at) {
  ivec2 marched_size = textureSize(u_marched, 0);
  // Where the pixel lies among the marched ones' sources (marched pixel i
  // stands for full-resolution pixel i u_factor + u_factor / 2).
  vec2 x = vec2(at - ivec2(u_factor / 2)) / float(u_factor);
  ivec2 base = ivec2(floor(x));
  vec2 f = x - vec2(base);
  vec2 key = cloud_march_key(at);
  vec4 sum = vec4(0.0);
  float total = 0.0;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      ivec2 low = clamp(base + ivec2(i, j), ivec2(0), marched_size - 1);
      if (w <= 0.0 || !cloud_same_march(key, texelFetch(u_marched_keys, low, 0).xy)) continue;
      sum += w * texelFetch(u_marched, low, 0);
      total += w;
    }
  }
  return total > 0.0 ? sum / total : vec4(-1.0);
}

