// The clouds marched at the pass's resolution: one full-resolution pixel
// in each block of u_factor x u_factor (cloud_source_pixel), its rgb what
// the clouds add there and its alpha their transmittance, and the march's
// key (cloud_ray_key); over targets cleared to no clouds (0, 0, 0, 1) and
// no layer (0, 0).
#include "clouds/gpu/cloud_march.glsl"

layout(location = 0) out vec4 o_clouds;
layout(location = 1) out vec2 o_key;  // cloud_ray_key, for the blend

void main() {
  ivec2 at = cloud_source_pixel(ivec2(gl_FragCoord.xy));
  CloudRay ray;
  if (!cloud_ray(at, ray)) discard;
  o_clouds = cloud_march(at, ray);
  o_key = cloud_ray_key(ray);
}
