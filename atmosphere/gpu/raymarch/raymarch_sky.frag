// Nishita et al. 1993, single scattering by nested ray marching: along the
// view ray, VIEW_STEPS samples; at each, LIGHT_STEPS samples toward the sun
// for its transmittance, and the terrain's shadow (terrain_shadow.glsl). Also composites the opaque surfaces behind the
// atmosphere (aerial perspective), and draws the sun disk and the ground
// where no surface was drawn as every technique does (sun.glsl, ground.glsl).
#include "atmosphere/shaders/atmosphere_block.glsl"

// The sun's light is marched, never looked up.
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_to_top(atmosphere, r, mu, LIGHT_STEPS);
}
#include "atmosphere/shaders/sunlight.glsl"
#include "atmosphere/gpu/terrain_shadow.glsl"
#include "atmosphere/shaders/ground.glsl"
#include "atmosphere/gpu/sky_pixel.glsl"

in vec2 v_ndc;
layout(location = 0) out vec4 o_radiance;

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_surface;
uniform vec3 u_camera;  // atmosphere space, metres
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_near;
// The Moon's centre (atmosphere space) and radius; none while the radius
// is 0 (SkyFrame).
uniform vec4 u_moon;

// The visible share of the sun at p: 1 but in an eclipse.
vec3 moon_sun_share(Atmosphere atmosphere, vec3 p) {
  if (u_moon.w <= 0.0) return vec3(1.0);
  return occluded_sun_fraction(u_sun_dir, atmosphere.sun_angular_radius, u_moon.xyz - p, u_moon.w);
}

void main() {
  Atmosphere atmosphere = block_atmosphere();
  SkyPixel pixel = sky_pixel(atmosphere, u_depth, u_surface, v_ndc, u_ray_from_ndc, u_near, u_camera);
  float depth = pixel.depth;
  vec3 surface = pixel.surface;
  vec3 dir = pixel.dir;
  float t_surface = pixel.t_surface;
  vec3 camera = pixel.camera;

  vec3 radiance = vec3(0.0);
  vec3 optical_depth = vec3(0.0);
  float t_top_near, t_top_far;
  bool in_atmosphere_ray = ray_sphere(camera, dir, atmosphere.top_radius, t_top_near, t_top_far) &&
                           t_top_far > 0.0;
  bool hits_ground = false;
  if (in_atmosphere_ray) {
    float t_start = max(t_top_near, 0.0);
    float t_end = t_top_far;
    // The air ends at the bottom sphere, or in front of a surface whose
    // ground lies below the datum, down at that ground (air_floor_radius).
    float floor_r = depth > 0.0 ? air_floor_radius(atmosphere) : atmosphere.bottom_radius;
    float t_ground_near, t_ground_far;
    if (ray_sphere(camera, dir, floor_r, t_ground_near, t_ground_far) && t_ground_near > 0.0) {
      hits_ground = true;
      t_end = min(t_end, t_ground_near);
    }
    t_end = min(t_end, t_surface);
    // Rebase the march at the atmosphere's entry: from far away the
    // camera's own coordinates have too few bits left for 10 m steps.
    vec3 origin = camera + t_start * dir;
    float segment = max(t_end - t_start, 0.0);
    float nu = dot(dir, u_sun_dir);
    float phase_r = rayleigh_phase(nu);
    float phase_m = mie_phase(atmosphere, nu);
    // From inside the atmosphere samples crowd near the camera (s = u^2),
    // where the air is densest; from outside they are spread evenly.
    bool inside = t_top_near <= 0.0;
    for (int i = 0; i < VIEW_STEPS; ++i) {
      float u = (float(i) + 0.5) / float(VIEW_STEPS);
      float s = inside ? segment * u * u : segment * u;
      float ds = inside ? segment * 2.0 * u / float(VIEW_STEPS) : segment / float(VIEW_STEPS);
      vec3 p = origin + s * dir;
      float r = length(p);
      float altitude = r - atmosphere.bottom_radius;
      vec3 extinction = extinction_at(atmosphere, altitude);
      vec3 transmittance_to_camera = exp(-(optical_depth + 0.5 * extinction * ds));
      optical_depth += extinction * ds;
      vec3 transmittance_to_sun = sun_visibility(atmosphere, r, dot(p, u_sun_dir) / r) *
                                  terrain_sun_visibility(p) * moon_sun_share(atmosphere, p);
      vec3 scattering =
          atmosphere.rayleigh_scattering *
              profile_density(atmosphere.rayleigh_density, altitude) * phase_r +
          atmosphere.mie_scattering * profile_density(atmosphere.mie_density, altitude) * phase_m;
      radiance += transmittance_to_camera * transmittance_to_sun * scattering * ds;
    }
    radiance *= atmosphere.solar_irradiance;
  }
  vec3 transmittance = exp(-optical_depth);
  // Where the ray meets the bottom sphere but no surface was drawn (the
  // mesh's flat facets sag below the true ellipsoid near the horizon), the
  // sphere itself is the ground: Lambertian with the model's albedo.
  if (depth == 0.0 && hits_ground) {
    float t_ground_near, t_ground_far;
    ray_sphere(camera, dir, atmosphere.bottom_radius, t_ground_near, t_ground_far);
    vec3 ground = camera + t_ground_near * dir;
    surface = atmosphere.solar_irradiance * ground_radiance(atmosphere, ground, u_sun_dir) *
              moon_sun_share(atmosphere, ground);
  }
  radiance += transmittance * surface;

  // The limb-darkened sun disk, on open sky only.
  float t_moon_near, t_moon_far;
  bool behind_moon = u_moon.w > 0.0 &&
                     ray_sphere(camera - u_moon.xyz, dir, u_moon.w, t_moon_near, t_moon_far) &&
                     t_moon_far > 0.0;
  if (depth == 0.0 && !hits_ground && !behind_moon) {
    radiance += transmittance * sun_disk_radiance(atmosphere, dot(dir, u_sun_dir));
  }
  // Keep within half-float range for the HDR target.
  o_radiance = vec4(min(radiance, vec3(6.0e4)), 1.0);
}
