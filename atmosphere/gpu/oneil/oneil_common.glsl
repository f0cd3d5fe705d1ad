// What the oneil technique's shaders share: the atmosphere's block, O'Neil's
// functions (oneil_functions.glsl) with the two scale functions from
// uniforms, the frame's camera and sun, and the light along one ray, which
// the dome's and the grid's vertices evaluate and a pixel that the grid's
// interpolation cannot serve evaluates for itself.
#include "atmosphere/shaders/atmosphere_block.glsl"
#include "atmosphere/shaders/oneil_definitions.glsl"

// The Moon's centre (atmosphere space) and radius; none while the radius
// is 0 (SkyFrame). Each sample of the single scattering takes the sun's
// visible share there, as raymarch's does.
uniform vec4 u_moon;
Real3 eclipse_sun_share(IN(Real3) p, IN(Real3) sun_dir) {
  if (u_moon.w <= 0.0) return Real3(1.0);
  return occluded_sun_fraction(sun_dir, block_atmosphere().sun_angular_radius, u_moon.xyz - p,
                               u_moon.w);
}
#include "atmosphere/shaders/oneil_functions.glsl"
#include "atmosphere/gpu/lifted_horizon.glsl"

uniform vec3 u_camera;  // atmosphere space, metres
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_near;
uniform vec2 u_viewport;
uniform vec2 u_scale_heights;  // Rayleigh, Mie
uniform float u_rayleigh_c[kOneilTerms];
uniform float u_mie_c[kOneilTerms];

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_surface;

// The kind is the program's constant (SCALE_KIND), not a uniform: the
// compiler then drops the other kind's code, which a SIMD rasteriser would
// otherwise run beside it.
OneilScale rayleigh_scale() {
  OneilScale s;
  s.scale_height = u_scale_heights.x;
  s.kind = SCALE_KIND;
  for (int i = 0; i < kOneilTerms; ++i) s.c[i] = u_rayleigh_c[i];
  return s;
}

OneilScale mie_scale() {
  OneilScale s;
  s.scale_height = u_scale_heights.y;
  s.kind = SCALE_KIND;
  for (int i = 0; i < kOneilTerms; ++i) s.c[i] = u_mie_c[i];
  return s;
}

// The sun's light through the atmosphere from the scale function, for the
// ground where no surface was drawn (ground.glsl).
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  Real2 columns = Real2(oneil_column(atmosphere, rayleigh_scale(), r, mu),
                        oneil_column(atmosphere, mie_scale(), r, mu));
  return exp(-oneil_extinction(atmosphere, columns));
}
#include "atmosphere/shaders/sunlight.glsl"
#include "atmosphere/shaders/ground.glsl"

// Reversed-Z with an infinite far plane: no surface is this far.
const float kFar = 3.0e38;

// A camera a hair below the bottom sphere (the ground mesh is an ellipsoid
// mapped onto it, up to float rounding) or inside the planet is lifted
// onto it, as every technique does.
vec3 oneil_camera(Atmosphere atmosphere) {
  float r = length(u_camera);
  float r_min = atmosphere.bottom_radius + 1.0;
  return r < r_min ? u_camera * (r_min / r) : u_camera;
}

// The unnormalised direction of the ray through an NDC point.
vec3 ray_at_ndc(vec2 ndc) { return u_ray_from_ndc * vec3(ndc, 1.0); }

// The distance to the surface drawn at a pixel (kFar for none).
float surface_distance(ivec2 pixel, float ray_scale) {
  float depth = texelFetch(u_depth, pixel, 0).r;
  return depth > 0.0 ? ray_scale * u_near / depth : kFar;
}

bool ray_hits_ground(Atmosphere atmosphere, vec3 camera, vec3 dir, out float t_ground) {
  float t_far;
  return ray_sphere(camera, dir, atmosphere.bottom_radius, t_ground, t_far) && t_ground > 0.0;
}

// A pixel's own ray and what it meets.
struct OneilPixel {
  ivec2 pixel;
  vec3 dir;         // unit
  vec3 camera;      // oneil_camera's
  float t_surface;  // distance to the drawn surface; kFar for none
  bool hits_ground;
  float t_ground;   // distance to the bottom sphere, where hits_ground
};

// frag_coord: the fragment's gl_FragCoord.xy.
OneilPixel oneil_pixel(Atmosphere atmosphere, vec2 frag_coord) {
  OneilPixel p;
  p.pixel = ivec2(frag_coord);
  vec3 ray = ray_at_ndc(frag_coord / u_viewport * 2.0 - 1.0);
  float ray_scale = length(ray);
  p.dir = ray / ray_scale;
  p.camera = oneil_camera(atmosphere);
  p.t_surface = surface_distance(p.pixel, ray_scale);
  if (p.t_surface == kFar) {
    p.dir = over_the_lifted_horizon(atmosphere, p.camera, length(u_camera), p.dir);
  }
  p.hits_ground = ray_hits_ground(atmosphere, p.camera, p.dir, p.t_ground);
  return p;
}

// The light leaving the bottom sphere at p, lit by the share of the sun
// the Moon leaves there.
vec3 oneil_sphere_radiance(Atmosphere atmosphere, vec3 p) {
  return atmosphere.solar_irradiance * ground_radiance(atmosphere, p, u_sun_dir) *
         eclipse_sun_share(p, u_sun_dir);
}

// The radiance leaving what the pixel's ray meets: the drawn surface, or
// where none was drawn (the mesh's flat facets sag below the true
// ellipsoid near the horizon) the bottom sphere itself, Lambertian with the
// model's albedo.
vec3 oneil_surface(Atmosphere atmosphere, OneilPixel p) {
  if (p.t_surface < kFar) return texelFetch(u_surface, p.pixel, 0).rgb;
  return oneil_sphere_radiance(atmosphere, p.camera + p.t_ground * p.dir);
}

// The light along the ray camera + t dir (unit dir) up to t_surface, the
// bottom sphere or the top: in-scattered Rayleigh and Mie light per unit
// phase function and the transmittance, with the sum started where the ray
// enters the atmosphere (from far away the camera's own coordinates have
// too few bits left for the samples). `samples` along it: SAMPLES, or 0
// where the result will not be used.
void oneil_ray(Atmosphere atmosphere, vec3 camera, vec3 dir, float t_surface, int samples,
               out vec3 rayleigh, out vec3 mie, out vec3 transmittance) {
  rayleigh = vec3(0.0);
  mie = vec3(0.0);
  transmittance = vec3(1.0);
  float t_top_near, t_top_far;
  if (!ray_sphere(camera, dir, atmosphere.top_radius, t_top_near, t_top_far) || t_top_far <= 0.0) {
    return;
  }
  float t_start = max(t_top_near, 0.0);
  float t_ground;
  bool hits_ground = ray_hits_ground(atmosphere, camera, dir, t_ground);
  float t_end = min(hits_ground ? min(t_top_far, t_ground) : t_top_far, t_surface);
  if (t_end <= t_start) return;
  vec3 origin = camera + t_start * dir;
  oneil_single_scattering(atmosphere, rayleigh_scale(), mie_scale(), origin, dir, hits_ground, 0.0,
                          t_end - t_start, u_sun_dir, samples, rayleigh, mie, transmittance);
}

// The phase functions per pixel (O'Neil's Mie phase is Cornette and
// Shanks's, as the other techniques').
vec3 oneil_phased(Atmosphere atmosphere, vec3 rayleigh, vec3 mie, vec3 dir) {
  float nu = dot(dir, u_sun_dir);
  return rayleigh * rayleigh_phase(nu) + mie * mie_phase(atmosphere, nu);
}

// The sun's disk seen from camera along dir, but where the Moon hides it.
vec3 oneil_sun_disk(Atmosphere atmosphere, vec3 camera, vec3 dir) {
  if (moon_hides_sun(camera, dir, u_moon.xyz, u_moon.w)) return vec3(0.0);
  return sun_disk_radiance(atmosphere, dot(dir, u_sun_dir));
}

uniform float u_exposure;

// Radiance for the frame's tone map, kept within half-float range; or, with
// the chapter's exposure, its display value 1 - exp(-exposure L) (the frame
// then leaves it as it is).
vec4 oneil_output(vec3 radiance) {
#ifdef CHAPTER_EXPOSURE
  return vec4(vec3(1.0) - exp(-u_exposure * radiance), 1.0);
#else
  return vec4(min(radiance, vec3(6.0e4)), 1.0);
#endif
}
