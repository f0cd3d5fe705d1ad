// The full-resolution pixels that no marched neighbour stands for
// (cloud_upsample.glsl) marched themselves; every other pixel discarded,
// so that the march runs only in the blocks of pixels that hold one.
#include "clouds/gpu/cloud_upsample.glsl"

layout(location = 0) out vec4 o_clouds;

void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  CloudRay ray;
  if (cloud_upsampled(at).a >= 0.0 || !cloud_ray(at, ray)) discard;
  o_clouds = cloud_march(at, ray);
}
