// Hillaire 2020, sec. 5.3-5.6: the sky, the sun disk and the aerial
// perspective over the opaque surfaces. Two paths, weighted by
// u_lut_weight, which the technique sets from the camera's altitude:
//  - the LUT path (inside the atmosphere): the sky-view LUT for open sky
//    (less what the terrain's shadow takes within the froxels' range), the
//    froxel volume for surfaces within its range and a per-pixel march
//    beyond it;
//  - the per-pixel path (high up and in space): a march of every pixel with
//    the same multiple-scattering LUT.
// Between the two altitudes both run and are blended, so that nothing pops.
//
// On the LUT path alone the pass is drawn in two parts: every pixel by
// this shader compiled with NO_MARCH, then the whole shader over the 8 x 8
// tiles with a surface past the froxels' blend (sky_march_tiles.comp,
// sky_tiles.vert). llvmpipe runs both sides of a branch, and a loop's body
// at least once, for every pixel of a block: on the ground a march behind
// an `if` took most of the pass's time over sky that takes no step of it,
// and a discarded pixel still runs the shader with its block. The pixel's
// NDC comes from its window position, so that both parts see the same.
//
// The first part also leaves out the sun's disk (NO_SUN_DISK), whose
// transmittance lookup and limb darkening took a sixth of it on the
// ground; the whole shader then draws again the few pixels of the sun's
// screen bound.
//
// The first part is itself drawn in two, each held by the stencil (which
// a classifying pass, CLASSIFY, sets to 1 under the surfaces) to the
// pixels it serves: OPEN_SKY_ONLY for the pixels without a surface, which
// read the sky-view LUT and no surface, SURFACE_ONLY for those with one,
// which read the froxels. Compiled as one, every pixel paid for both: on
// the ground the sky pass took 44 ms at 1280x720, in parts 30.
//
// For frames on the per-pixel path alone (u_lut_weight 0), the shader is
// compiled with NO_LUT, without the LUT path, which llvmpipe would run
// over every pixel for a weight of 0; where the model's Mie scattering is
// grey, also with GREY_MIE (forward_gain). From outside the shell it is
// compiled with SPACE_VIEW_LUT too: the march's luminance and
// transmittance then come from the space-view LUT (space_view_lut.glsl),
// which the technique marches once for the camera's altitude and sun.
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"
#include "atmosphere/gpu/sky_pixel.glsl"

layout(location = 0) out vec4 o_radiance;
#if defined(OPEN_SKY_ONLY) || defined(SURFACE_ONLY)
layout(early_fragment_tests) in;
#endif

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_surface;
layout(binding = 4) uniform sampler2D u_sky_view_lut;
layout(binding = 5) uniform sampler3D u_aerial_scattering;
layout(binding = 6) uniform sampler3D u_aerial_transmittance;

uniform vec3 u_camera;  // atmosphere space, metres
uniform float u_camera_r;  // |camera| from double, lifted above the ground
uniform float u_sky_view_r;  // the radius the sky-view LUT was computed at (rounded)
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_near;
uniform vec2 u_viewport;
uniform mat3 u_local_from_atmo;  // rows: toward the sun's azimuth, across, up
uniform float u_lut_weight;
uniform float u_aerial_range;
#ifdef TERRAIN_SHADOWS
// The sunlight the terrain's shadow took from each froxel's ray
// (aerial_perspective.comp), weighted 0 when the froxels have no shadow.
layout(binding = 10) uniform sampler3D u_aerial_shadow_loss;
uniform float u_shadow_loss_weight;
#endif

// The march's steps, from the optical depth of the whole ray through the
// air (its worst channel, from the transmittance LUT; a ray that ends at
// a surface gets the steps of the whole ray): PER_PIXEL_STEPS from an
// optical depth of kFullStepsDepth, down to a third of them for a thin ray.
// On Earth a ray from space to the ground has an optical depth of about
// 0.3 to 0.5 (blue) and takes about 20 steps; a ray along the limb takes
// them all. At a
// fixed 20 steps the canonical space scenes moved by at most 0.6 points of
// error (asteroid_space), at 12 by 3.6 points.
const float kFullStepsDepth = 3.0;
int march_steps(Atmosphere atmosphere, vec3 origin, vec3 dir) {
  float r = length(origin);
  float mu = dot(origin, dir) / r;
  vec3 transmittance;
  if (ray_intersects_ground(atmosphere, r, mu)) {
    // Bruneton 2017's form: from the ground point back toward the origin,
    // less the part beyond the origin.
    float t = distance_to_bottom_boundary(atmosphere, r, mu);
    vec3 ground = origin + t * dir;
    float mu_ground = dot(ground, dir) / length(ground);
    transmittance = transmittance_lookup(atmosphere, atmosphere.bottom_radius, -mu_ground) /
                    max(transmittance_lookup(atmosphere, r, -mu), vec3(1e-30));
  } else {
    transmittance = transmittance_lookup(atmosphere, r, mu);
  }
  float depth = -log(max(min(transmittance.r, min(transmittance.g, transmittance.b)), 1e-30));
  int fewest = max(PER_PIXEL_STEPS / 4, 4);
  float f = clamp(depth / kFullStepsDepth, 0.0, 1.0);
  // Even: the march reads the multiple-scattering field once a pair.
  int steps = fewest + int(ceil(f * float(PER_PIXEL_STEPS - fewest)));
  return steps + (steps & 1);
}

#ifdef SPACE_VIEW_LUT
#include "atmosphere/gpu/hillaire/space_view_lut.glsl"
layout(binding = 12) uniform sampler2D u_space_open_sky;
layout(binding = 13) uniform sampler3D u_space_scattering;
layout(binding = 14) uniform sampler3D u_space_transmittance;
uniform float u_space_r;  // the camera's distance from the centre the LUT was made for
uniform vec2 u_ground_heights;  // the LUT's lowest and highest ground, metres

// What the march below would give over the same range, from the LUT: the
// whole ray for open sky (t_surface 3e38), else the air in front of the
// surface at t_surface, down to the altitude where the ray meets it. A
// surface past the ray's closest approach to the centre (a peak beyond the
// limb's tangent point) takes the air down to the closest approach.
void space_view(vec3 camera, vec3 dir, bool at_surface, float t_surface, out vec3 luminance,
                out vec3 transmittance) {
  luminance = vec3(0.0);
  transmittance = vec3(1.0);
  Atmosphere atmosphere = block_atmosphere();
  vec3 local = u_local_from_atmo * dir;
  float cos_nadir = -local.z;
  float p = u_space_r * safe_sqrt(1.0 - cos_nadir * cos_nadir);
  if (cos_nadir <= 0.0 || p >= atmosphere.top_radius) return;
  float phi = atan(abs(local.y), local.x);
  vec2 uv = vec2(space_view_u_from_phi(phi), space_view_v_from_p(atmosphere, p));
  // The air down to the surface, or for open sky down to the bottom sphere
  // (its half over the limb takes the whole ray instead).
  float b = dot(camera, dir);
  float rb = atmosphere.bottom_radius;
  float h = !at_surface ? 0.0
                         : (t_surface >= -b ? p - rb : length(camera + t_surface * dir) - rb);
  vec3 w = vec3(uv, space_view_w_from_altitude(u_ground_heights, h));
  luminance = texture(u_space_scattering, w).rgb;
  transmittance = texture(u_space_transmittance, w).rgb;
  if (!at_surface && p < rb) {
    // The ground lit behind the air; no sun's disk through the planet.
    float t_ground = -b - safe_sqrt(rb * rb - p * p);
    luminance += transmittance * ground_radiance(atmosphere, camera + t_ground * dir, u_sun_dir);
    transmittance = vec3(0.0);
  } else if (!at_surface) {
    // The whole ray, and for the sun's disk behind the limb its
    // transmittance, from where it enters the shell.
    luminance = texture(u_space_open_sky, uv).rgb;
    float top = atmosphere.top_radius;
    vec3 enter = camera + (-b - safe_sqrt(top * top - p * p)) * dir;
    transmittance = transmittance_lookup(atmosphere, top, dot(enter, dir) / top);
  }
  luminance *= atmosphere.solar_irradiance;
}
#endif

// A march from the camera over [0, t_max] of the ray: luminance (with the
// solar irradiance) and transmittance. From outside the atmosphere the
// march starts where the ray enters it, so that the samples keep their
// precision however far the camera is.
void march(vec3 camera, vec3 dir, float t_max, bool with_ground, out vec3 luminance,
           out vec3 transmittance) {
  luminance = vec3(0.0);
  transmittance = vec3(1.0);
  Atmosphere atmosphere = block_atmosphere();
  float t_top_near, t_top_far;
  if (!ray_sphere(camera, dir, atmosphere.top_radius, t_top_near, t_top_far) || t_top_far <= 0.0) {
    return;
  }
  float t_start = max(t_top_near, 0.0);
  float t_end = min(t_top_far, t_max);
  if (t_end <= t_start) return;
  vec3 origin = camera + t_start * dir;
  vec3 f_ms;
  integrate_along(atmosphere, origin, dir, 0.0, t_end - t_start, u_sun_dir,
                  march_steps(atmosphere, origin, dir), kSourceSky, kFieldPerPair, with_ground,
                  luminance, transmittance, f_ms);
  luminance *= atmosphere.solar_irradiance;
}

// The sun's disk seen from camera along dir, but where the Moon hides it
// (as raymarch's).
vec3 sun_disk(vec3 camera, vec3 dir, vec3 transmittance) {
  Atmosphere atmosphere = block_atmosphere();
  if (moon_hides_sun(camera, dir, u_moon.xyz, u_moon.w)) return vec3(0.0);
  return transmittance * sun_disk_radiance(atmosphere, dot(dir, u_sun_dir));
}

// Aerial perspective of a surface at distance t from the froxel volume.
void froxel(float t, out vec3 scattering, out vec3 transmittance) {
  vec2 uv = gl_FragCoord.xy / u_viewport;
  float w = aerial_slice_coord(u_aerial_range, t);
  float w0 = 0.5 / float(kAerialPerspectiveSize);
  scattering = texture(u_aerial_scattering, vec3(uv, max(w, w0))).rgb;
  transmittance = texture(u_aerial_transmittance, vec3(uv, max(w, w0))).rgb;
  // Nearer than the first slice's centre: fade from nothing at the camera.
  if (w < w0) {
    float f = (w * w) / (w0 * w0);
    scattering *= f;
    transmittance = mix(vec3(1.0), transmittance, f);
  }
  scattering *= block_atmosphere().solar_irradiance;
}

#ifdef CLASSIFY
// Keeps the pixels with a surface, whose stencil the pass sets.
void main() {
  if (texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r == 0.0) discard;
  o_radiance = vec4(0.0);
}
#else
void main() {
  Atmosphere atmosphere = block_atmosphere();
  vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
  SkyPixel pixel = sky_pixel(atmosphere, u_depth, u_surface, ndc, u_ray_from_ndc, u_near, u_camera);
  vec3 dir = pixel.dir;
  vec3 camera = pixel.camera;
  const float kFar = 3.0e38;
  // Whether an opaque surface lies under the pixel: as the stencil holds
  // it where a program serves one kind of pixel alone, so that the other
  // kind's code goes, and for the open sky no surface is read.
#if defined(OPEN_SKY_ONLY)
  const bool at_surface = false;
  const vec3 surface = vec3(0.0);
  float t_surface = kFar;
#else
#ifdef SURFACE_ONLY
  const bool at_surface = true;
#else
  bool at_surface = pixel.depth > 0.0;
#endif
  vec3 surface = pixel.surface;
  float t_surface = pixel.t_surface;
#endif

  // The air in front of a surface ends at the bottom sphere: a coarse tile's
  // facets are chords that sag below it (km from high up). From 400 km the
  // march through the sag made the ground near the limb 5-8 % too bright.
  // Where the ground under the pixel lies below the datum, its air goes
  // down to it (air_floor_radius). Open sky meets the bottom sphere.
  float floor_r = at_surface ? air_floor_radius(atmosphere) : atmosphere.bottom_radius;
  float t_ground_near, t_ground_far;
  bool hits_ground =
      ray_sphere(camera, dir, floor_r, t_ground_near, t_ground_far) && t_ground_near > 0.0;
  bool open_sky = !at_surface && !hits_ground;
  if (at_surface && hits_ground) t_surface = min(t_surface, t_ground_near);

  // Froxels near, the per-pixel march beyond; blended over the last fifth
  // of the volume's range so that no edge shows on the ground.
  float blend = smoothstep(0.8 * u_aerial_range, u_aerial_range, t_surface);
  // One march serves both paths: in front of a surface they march the
  // same range. llvmpipe runs both sides of a branch on a uniform; with a
  // march on each side the sky pass took 130 ms on the ground (now 84) and
  // 774 ms at 400 km (now 737).
  vec3 march_luminance = vec3(0.0), march_transmittance = vec3(1.0);
#ifndef NO_MARCH
  if (u_lut_weight < 1.0 || (at_surface && blend > 0.0)) {
#ifdef SPACE_VIEW_LUT
    space_view(camera, dir, at_surface, t_surface, march_luminance, march_transmittance);
#else
    float t_max = at_surface ? t_surface : (hits_ground ? t_ground_near : kFar);
    march(camera, dir, t_max, !at_surface && hits_ground, march_luminance, march_transmittance);
#endif
  }
#endif

  vec3 lut_radiance = vec3(0.0);
#ifndef NO_LUT
  if (u_lut_weight > 0.0) {
    if (at_surface) {
      vec3 near_radiance = vec3(0.0);
      if (blend < 1.0) {
        vec3 scattering, transmittance;
        froxel(t_surface, scattering, transmittance);
        near_radiance = scattering + transmittance * surface;
      }
      vec3 far_radiance = march_luminance + march_transmittance * surface;
      lut_radiance = mix(near_radiance, far_radiance, blend);
    } else {
      vec3 local = u_local_from_atmo * dir;
      float u, v;
      sky_view_lut_uv_from_view(atmosphere, u_sky_view_r, local.z, atan(local.y, local.x), u, v);
      lut_radiance = texture(u_sky_view_lut, vec2(u, v)).rgb * atmosphere.solar_irradiance;
#ifdef TERRAIN_SHADOWS
      // The sky-view LUT knows no terrain: take off the sunlight that the
      // terrain's shadow took within the froxels' range (their last slice).
      vec3 loss = texture(u_aerial_shadow_loss,
                          vec3(gl_FragCoord.xy / u_viewport,
                               1.0 - 0.5 / float(kAerialPerspectiveSize))).rgb;
      lut_radiance = max(lut_radiance - u_shadow_loss_weight * loss * atmosphere.solar_irradiance,
                         vec3(0.0));
#endif
#ifndef NO_SUN_DISK
      if (open_sky) {
        float mu = dot(camera, dir) / length(camera);
        lut_radiance += sun_disk(camera, dir, transmittance_lookup(atmosphere, u_camera_r, mu));
      }
#endif
    }
  }
#endif

  vec3 march_radiance = march_luminance + march_transmittance * surface;
#ifndef NO_SUN_DISK
  if (open_sky) march_radiance += sun_disk(camera, dir, march_transmittance);
#endif

  vec3 radiance = mix(march_radiance, lut_radiance, u_lut_weight);
  // Within half-float range, so that a 16-bit target cannot overflow.
  o_radiance = vec4(min(radiance, vec3(6.0e4)), 1.0);
}
#endif
