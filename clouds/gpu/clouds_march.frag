// The clouds marched at the pass's resolution: one full-resolution pixel
// in each block of u_factor x u_factor (cloud_source_pixel), its rgb what
// the clouds add there and its alpha their transmittance; over a target
// cleared to no clouds (0, 0, 0, 1).
#include "clouds/gpu/cloud_march.glsl"

layout(location = 0) out vec4 o_clouds;

void main() {
  ivec2 at = cloud_source_pixel(ivec2(gl_FragCoord.xy));
  CloudRay ray;
  if (!cloud_ray(at, ray)) discard;
  o_clouds = cloud_march(at, ray);
}
