// The first of the technique's passes: sorts the pixels for the others
// through the stencil (oneil_technique.cpp). It keeps, and marks as the
// sky's, the pixels whose ray meets neither a drawn surface nor the bottom
// sphere, and gives them the sun's disk as seen from space, which the rays
// that miss the atmosphere keep and the dome overwrites on the rest. The
// other pixels are the grid's.
#include "atmosphere/gpu/oneil/oneil_common.glsl"

layout(location = 0) out vec4 o_radiance;

void main() {
  // A drawn surface first, from its depth alone: llvmpipe skips the rest
  // of the shader for a batch of pixels that are all discarded.
  if (texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r > 0.0) discard;
  Atmosphere atmosphere = block_atmosphere();
  OneilPixel p = oneil_pixel(atmosphere, gl_FragCoord.xy);
  if (p.t_surface < kFar || p.hits_ground) discard;
  o_radiance = oneil_output(oneil_sun_disk(atmosphere, p.camera, p.dir));
}
