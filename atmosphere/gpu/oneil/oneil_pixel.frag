// The grid's pixels that its interpolation could not serve (left unmarked
// in the stencil by oneil_ground.frag): each sums the light along its own
// ray, as the grid's vertices do.
#include "atmosphere/gpu/oneil/oneil_common.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 o_radiance;

void main() {
  Atmosphere atmosphere = block_atmosphere();
  OneilPixel p = oneil_pixel(atmosphere, gl_FragCoord.xy);
  vec3 rayleigh, mie, transmittance;
  oneil_ray(atmosphere, p.camera, p.dir, p.t_surface, SAMPLES, rayleigh, mie, transmittance);
  o_radiance = oneil_output(oneil_surface(atmosphere, p) * transmittance +
                            oneil_phased(atmosphere, rayleigh, mie, p.dir));
}
