// The sky dome's pixels: the interpolated light with the phase functions of
// the pixel's own ray, and the sun's disk through the transmittance. Only
// the pixels the stencil marks as sky are shaded; those whose ray meets a
// surface or the ground are the grid's.
#include "atmosphere/gpu/oneil/oneil_common.glsl"

layout(early_fragment_tests) in;
in vec3 v_rayleigh;
in vec3 v_mie;
in vec3 v_transmittance;
layout(location = 0) out vec4 o_radiance;

void main() {
  Atmosphere atmosphere = block_atmosphere();
  // A ray below a lifted camera's horizon is the sky just above it
  // (lifted_horizon.glsl), phases included.
  vec3 camera = oneil_camera(atmosphere);
  vec3 dir = over_the_lifted_horizon(
      atmosphere, camera, length(u_camera),
      normalize(ray_at_ndc(gl_FragCoord.xy / u_viewport * 2.0 - 1.0)));
  vec3 radiance = oneil_phased(atmosphere, v_rayleigh, v_mie, dir) +
                  v_transmittance * oneil_sun_disk(atmosphere, camera, dir);
  o_radiance = oneil_output(radiance);
}
