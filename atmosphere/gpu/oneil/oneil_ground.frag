// The opaque surfaces seen through the atmosphere (surface * transmittance
// + in-scattered light), from the grid's vertices, over the grid's pixels
// (as the stencil marks them). A pixel that the interpolation cannot serve
// is discarded, and oneil_pixel.frag sums it on its own ray: by a
// silhouette (the inverse distance more than DISTANCE_TOLERANCE off the
// interpolated one), or next to open sky. The bottom sphere where no surface
// was drawn (the mesh's flat facets sag below the true ellipsoid near the
// horizon; in hollows below the sphere; in the canonical scenes, the whole
// ground) is served like a surface, with the light leaving it interpolated
// between the vertices.
#include "atmosphere/gpu/oneil/oneil_common.glsl"

in vec3 v_rayleigh;
in vec3 v_mie;
in vec3 v_transmittance;
in float v_inverse_distance;
in float v_sky;
in vec3 v_sphere_radiance;
in float v_on_sphere;
layout(location = 0) out vec4 o_radiance;

void main() {
  if (v_sky > 0.0) discard;
  Atmosphere atmosphere = block_atmosphere();
  OneilPixel p = oneil_pixel(atmosphere, gl_FragCoord.xy);
  if (p.t_surface == kFar && v_on_sphere < 1.0) discard;
  float distance = p.t_surface < kFar ? p.t_surface : p.t_ground;
  if (abs(v_inverse_distance * distance - 1.0) > DISTANCE_TOLERANCE) discard;
  vec3 surface = p.t_surface < kFar ? texelFetch(u_surface, p.pixel, 0).rgb : v_sphere_radiance;
  o_radiance = oneil_output(surface * v_transmittance +
                            oneil_phased(atmosphere, v_rayleigh, v_mie, p.dir));
}
