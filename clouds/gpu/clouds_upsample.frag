// The clouds at full resolution where the marched pixels around a pixel
// end as it does (cloud_upsample.glsl); no clouds (0, 0, 0, 1) where none
// does, which clouds_fill.frag then marches.
#include "clouds/gpu/cloud_upsample.glsl"

layout(location = 0) out vec4 o_clouds;

void main() {
  vec4 blended = cloud_upsampled(ivec2(gl_FragCoord.xy));
  o_clouds = blended.a >= 0.0 ? blended : vec4(0.0, 0.0, 0.0, 1.0);
}
