// The space-view LUT (space_view_lut.glsl) for a camera at u_camera_r,
// outside the shell: one invocation per (phi, p), which marches its ray
// down through the slices, and over the limb once more whole, for the
// open sky.
// Luminance is per unit solar irradiance, as the sky-view LUT's.
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"
#include "atmosphere/gpu/hillaire/space_view_lut.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_open_sky;
layout(rgba16f, binding = 1) uniform writeonly image3D u_scattering;
layout(rgba16f, binding = 2) uniform writeonly image3D u_transmittance;

uniform float u_camera_r;      // outside the top sphere
uniform vec3 u_sun_dir_local;  // (sin, 0, cos) of the sun's zenith angle at the camera
uniform vec2 u_ground;         // the ground's lowest and highest altitudes, metres

// The altitude the march has come down to after segment n: the first
// kSpaceViewUpperSegments from the top to the highest ground (square law,
// finer low down), then one a slice, from slice kSpaceViewLutDepth - 2 to 0.
const int kSegments = kSpaceViewUpperSegments + kSpaceViewLutDepth - 1;
float segment_end_altitude(Atmosphere atmosphere, int n) {
  const int upper = kSpaceViewUpperSegments;
  float top = atmosphere.top_radius - atmosphere.bottom_radius;
  float hi = space_view_slice_altitude(u_ground, kSpaceViewLutDepth - 1);
  if (n < upper) {
    float s = float(upper - 1 - n) / float(upper);
    return hi + (top - hi) * s * s;
  }
  return space_view_slice_altitude(u_ground, kSpaceViewLutDepth - 2 - (n - upper));
}

// How far along origin + t dir (origin on the top sphere, dir inward) the
// ray comes down to altitude h: the nearer crossing of its sphere, or the
// closest approach where it never does; not before t_after.
float distance_down_to(Atmosphere atmosphere, vec3 origin, vec3 dir, float h, float t_after) {
  float radius = atmosphere.bottom_radius + h;
  float b = dot(origin, dir);
  float t_closest = max(-b, 0.0);
  float disc = radius * radius - (dot(origin, origin) - b * b);
  float t = disc > 0.0 ? min(-b - sqrt(disc), t_closest) : t_closest;
  return max(t, t_after);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= kSpaceViewLutWidth || texel.y >= kSpaceViewLutHeight) return;
  Atmosphere atmosphere = block_atmosphere();
  float p = space_view_p_from_row(atmosphere, texel.y);
  float phi = space_view_phi_from_column(texel.x);
  float sin_nadir = min(p / u_camera_r, 1.0);
  float cos_nadir = safe_sqrt(1.0 - sin_nadir * sin_nadir);
  vec3 dir = vec3(sin_nadir * cos(phi), sin_nadir * sin(phi), -cos_nadir);
  vec3 camera = vec3(0.0, 0.0, u_camera_r);
  // Where the ray enters the shell; the march starts there, as the sky
  // pass's does, so that its samples keep their precision.
  float t_enter, t_leave;
  ray_sphere(camera, dir, atmosphere.top_radius, t_enter, t_leave);
  vec3 origin = camera + max(t_enter, 0.0) * dir;

  // Open sky over the limb: the whole ray. (A ray that meets the ground
  // is the slices' down to altitude 0 and the lit ground: the sky pass
  // adds the ground itself.)
  vec3 f_ms;
  if (p >= atmosphere.bottom_radius) {
    float t_end;
    bool hits_ground;
    ray_extent_inside(atmosphere, origin, dir, t_end, hits_ground);
    vec3 luminance, transmittance;
    integrate_along(atmosphere, origin, dir, 0.0, t_end, u_sun_dir_local, SPACE_VIEW_STEPS,
                    kSourceSky, kFieldPerPair, false, luminance, transmittance, f_ms);
    imageStore(u_open_sky, texel, vec4(luminance, 1.0));
  } else {
    imageStore(u_open_sky, texel, vec4(0.0));
  }

  // The slices: only where a ray of this row or the one below it comes
  // down to the highest ground (a pixel's lookup may blend the two).
  float hi = space_view_slice_altitude(u_ground, kSpaceViewLutDepth - 1);
  float rb = atmosphere.bottom_radius;
  if (texel.y > 0 && space_view_p_from_row(atmosphere, texel.y - 1) - rb > hi) return;
  // From the top down, one segment after another (segment_end_altitude);
  // each pair of them shares one read of the multiple-scattering field, at
  // the pair's middle. Past the closest approach the slices hold the same.
  float nu = dot(dir, u_sun_dir_local);
  float phase_r = rayleigh_phase(nu);
  float phase_m = mie_phase(atmosphere, nu);
  vec3 scattering = vec3(0.0), throughput = vec3(1.0);
  f_ms = vec3(0.0);
  float t_previous = 0.0;
  float t_closest = max(-dot(origin, dir), 0.0);
  FieldMoments field;
  for (int n = 0; n < kSegments; ++n) {
    float t_end = distance_down_to(atmosphere, origin, dir, segment_end_altitude(atmosphere, n),
                                   t_previous);
    if ((n & 1) == 0) {
      float t_pair = n + 1 < kSegments
                         ? distance_down_to(atmosphere, origin, dir,
                                            segment_end_altitude(atmosphere, n + 1), t_end)
                         : t_end;
      field = field_at_point(atmosphere, false, origin + (0.5 * (t_previous + t_pair)) * dir,
                             u_sun_dir_local);
    }
    vec3 x = origin + (0.5 * (t_previous + t_end)) * dir;
    vec3 field_r, field_m;
    field_radiance(atmosphere, field, length(x), x, dir, u_sun_dir_local, field_r, field_m);
    accumulate_segment_in(atmosphere, origin, dir, t_previous, t_end, u_sun_dir_local, phase_r,
                          phase_m, kSourceSky, field_r, field_m, true, scattering, throughput,
                          f_ms);
    t_previous = t_end;
    // Slice k's altitude is where segment n ends, from n = upper - 1 on.
    int k = kSpaceViewLutDepth - 1 - (n - (kSpaceViewUpperSegments - 1));
    bool done = t_end >= t_closest;
    // Slice k, and where the ray came no lower, every slice below it.
    for (int j = min(k, kSpaceViewLutDepth - 1); j >= (done ? 0 : k); --j) {
      imageStore(u_scattering, ivec3(texel, j), vec4(scattering, 1.0));
      imageStore(u_transmittance, ivec3(texel, j), vec4(throughput, 1.0));
    }
    if (done) break;
  }
}
