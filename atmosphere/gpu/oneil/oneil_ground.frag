// The opaque surfaces and the bottom sphere, seen through the atmosphere:
// surface * transmittance + in-scattered light, from the grid's vertices
// where they describe this pixel's ray, else from the pixel's own ray: by a
// silhouette (its inverse distance more than DISTANCE_TOLERANCE off the
// interpolated one) or next to open sky. Open-sky pixels are the dome's,
// but for those whose rays miss the atmosphere, which show the sun alone.
#include "atmosphere/gpu/oneil/oneil_common.glsl"

in vec3 v_rayleigh;
in vec3 v_mie;
in vec3 v_transmittance;
in float v_inverse_distance;
in float v_sky;
layout(location = 0) out vec4 o_radiance;

void main() {
  Atmosphere atmosphere = block_atmosphere();
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 ray = ray_at_ndc(gl_FragCoord.xy / u_viewport * 2.0 - 1.0);
  float ray_scale = length(ray);
  vec3 dir = ray / ray_scale;
  vec3 camera = oneil_camera(atmosphere);
  float t_surface = surface_distance(pixel, ray_scale);
  float t_ground;
  bool ground = ray_hits_ground(atmosphere, camera, dir, t_ground);
  if (t_surface == kFar && !ground) {
    // Open sky is the dome's, but for the rays that miss the atmosphere
    // altogether (from space), where only the sun's disk shows.
    float t_top_near, t_top_far;
    if (ray_sphere(camera, dir, atmosphere.top_radius, t_top_near, t_top_far) && t_top_far > 0.0) {
      discard;
    }
    o_radiance = oneil_output(sun_disk_radiance(atmosphere, dot(dir, u_sun_dir)));
    return;
  }
  // Where no surface was drawn but the ray meets the bottom sphere (the
  // mesh's flat facets sag below the true ellipsoid near the horizon), the
  // sphere itself is the ground: Lambertian with the model's albedo.
  vec3 surface = t_surface < kFar ? texelFetch(u_surface, pixel, 0).rgb
                                  : atmosphere.solar_irradiance *
                                        ground_radiance(atmosphere, camera + t_ground * dir,
                                                        u_sun_dir);
  float distance = t_surface < kFar ? t_surface : t_ground;
  vec3 rayleigh = v_rayleigh, mie = v_mie, transmittance = v_transmittance;
  if (v_sky > 0.0 || abs(v_inverse_distance * distance - 1.0) > DISTANCE_TOLERANCE) {
    oneil_ray(atmosphere, camera, dir, t_surface, rayleigh, mie, transmittance);
  }
  o_radiance = oneil_output(surface * transmittance + oneil_phased(atmosphere, rayleigh, mie, dir));
}
