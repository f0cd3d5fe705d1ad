// Hillaire 2020, sec. 5.4: in-scattering and transmittance from the camera
// to the centre of each of 32 depth slices, for 32 x 32 screen columns
// (and with the terrain's shadow, the sunlight it took away on the way).
// One invocation marches its column once, slice after slice. The
// transmittance is kept per channel (RGB), not as a mean, so that distant
// ground turns blue-grey and a low sun's red comes through.
#ifdef TERRAIN_SHADOW_LOSS
// The sun's light the terrain's shadow took from the march so far
// (hillaire_functions.glsl adds to it): the open sky, drawn from the
// sky-view LUT that knows no terrain, takes it off.
vec3 terrain_shadow_loss = vec3(0.0);
#endif
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f, binding = 0) uniform writeonly image3D u_scattering;
layout(rgba16f, binding = 1) uniform writeonly image3D u_transmittance;
#ifdef TERRAIN_SHADOW_LOSS
layout(rgba16f, binding = 2) uniform writeonly image3D u_shadow_loss;
#endif

uniform vec3 u_camera;  // atmosphere space, lifted above the ground
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_range;  // metres along the ray to the last slice's centre

void main() {
  ivec2 column = ivec2(gl_GlobalInvocationID.xy);
  if (column.x >= kAerialPerspectiveSize || column.y >= kAerialPerspectiveSize) return;
  Atmosphere atmosphere = block_atmosphere();
  vec2 ndc = (vec2(column) + 0.5) / float(kAerialPerspectiveSize) * 2.0 - 1.0;
  vec3 dir = normalize(u_ray_from_ndc * vec3(ndc, 1.0));
  // The march goes on through the bottom sphere: the ground mesh's facets
  // lie below it (chords of the ellipsoid), so a surface may stand beyond
  // where the sphere would stop the ray. It ends only at the top.
  float t_top_near, t_end;
  ray_sphere(u_camera, dir, atmosphere.top_radius, t_top_near, t_end);
  t_end = max(t_end, 0.0);

  float nu = dot(dir, u_sun_dir);
  float phase_r = rayleigh_phase(nu);
  float phase_m = mie_phase(atmosphere, nu);
  vec3 luminance = vec3(0.0), throughput = vec3(1.0), f_ms = vec3(0.0);
  float t_previous = 0.0;
  for (int k = 0; k < kAerialPerspectiveSize; ++k) {
    float w = (float(k) + 0.5) / float(kAerialPerspectiveSize);
    // Beyond the top a slice holds what lies before it.
    float t_slice = min(aerial_slice_distance(u_range, w), t_end);
    for (int s = 0; s < AERIAL_SUBSTEPS; ++s) {
      float t0 = mix(t_previous, t_slice, float(s) / float(AERIAL_SUBSTEPS));
      float t1 = mix(t_previous, t_slice, float(s + 1) / float(AERIAL_SUBSTEPS));
      accumulate_segment(atmosphere, u_camera, dir, t0, t1, u_sun_dir, phase_r, phase_m,
                         kSourceSky, luminance, throughput, f_ms);
    }
    t_previous = t_slice;
    ivec3 froxel = ivec3(column, k);
    imageStore(u_scattering, froxel, vec4(luminance, 1.0));
    imageStore(u_transmittance, froxel, vec4(throughput, 1.0));
#ifdef TERRAIN_SHADOW_LOSS
    imageStore(u_shadow_loss, froxel, vec4(terrain_shadow_loss, 1.0));
#endif
  }
}
