// Bruneton 2017's rendering: the sky, the sun disk, and the aerial
// perspective over the opaque surfaces, from the precomputed tables, at any
// altitude (a camera in space looks from where its ray enters the top).
// One program per PASS (bruneton_technique.cpp), each restricted by the
// stencil to the pixels it serves, since a SIMD rasteriser runs every side
// of a branch: kClassifyPass marks, by CLASS, the pixels whose ray meets
// a surface or the ground (1), those of them next to the horizon (2), and
// those whose ray misses the atmosphere (3), giving the last the sun's
// disk; kSkyPass draws the sky through the atmosphere, kAerialPass the
// surfaces and the ground, kHorizonPass those next to the horizon. The
// plain schedule (gl/schedule.h) draws every pixel with kAllPass instead,
// which takes each pixel's class in its own branches.
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"
#include "atmosphere/gpu/sky_pixel.glsl"

#define kClassifyPass 0
#define kSkyPass 1
#define kAerialPass 2
#define kHorizonPass 3
#define kAllPass 4
#if PASS != kClassifyPass
layout(early_fragment_tests) in;
#endif

in vec2 v_ndc;
layout(location = 0) out vec4 o_radiance;

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_surface;
layout(binding = 2) uniform sampler2D u_transmittance;
layout(binding = 3) uniform sampler3D u_scattering;
layout(binding = 4) uniform sampler3D u_single_mie;  // without COMBINED
layout(binding = 5) uniform sampler2D u_irradiance;

uniform vec3 u_camera;  // atmosphere space, metres
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_near;
// The Moon's centre (atmosphere space) and radius; none while the radius
// is 0 (SkyFrame).
uniform vec4 u_moon;

// In an eclipse, the share of the sun a view ray's light takes from the
// Moon, one per ray: the tables hold a sun the same for the whole sky, so
// the ray's light, of every order, is multiplied by the mean of the
// visible share at points along it from t_start to t_end (to the top, the
// ground or a surface), weighted as its single scattering would weigh them
// (the air's extinction there times the transmittance back to the camera;
// the sun's own path left out). The first order's share is then right to
// that approximation, and the orders above it are taken as if the shadow
// were as wide as their light's reach (docs/eclipses.md#the-frame).
// 1 exactly with no Moon, so that it changes no other sky.
const int kEclipseShareSamples = 16;
vec3 eclipse_share_along(Atmosphere atmosphere, vec3 camera, vec3 dir, float t_end) {
  if (u_moon.w <= 0.0) return vec3(1.0);
  float t_near, t_far;
  if (!ray_sphere(camera, dir, atmosphere.top_radius, t_near, t_far) || t_far <= 0.0) {
    return vec3(1.0);
  }
  float t_start = max(t_near, 0.0);
  float span = max(min(t_end, t_far) - t_start, 0.0);
  vec3 weighted = vec3(0.0), weights = vec3(0.0), depth = vec3(0.0);
  // Crowded toward the start (t = span u^2), where a view from the ground
  // takes most of its light.
  for (int i = 0; i < kEclipseShareSamples; ++i) {
    float u = (float(i) + 0.5) / float(kEclipseShareSamples);
    float dt = span * 2.0 * u / float(kEclipseShareSamples);
    vec3 p = camera + (t_start + span * u * u) * dir;
    vec3 extinction = extinction_at(atmosphere, max(length(p) - atmosphere.bottom_radius, 0.0));
    vec3 w = extinction * dt * exp(-(depth + 0.5 * extinction * dt));
    depth += extinction * dt;
    weighted += w * occluded_sun_fraction(u_sun_dir, atmosphere.sun_angular_radius,
                                          u_moon.xyz - p, u_moon.w);
    weights += w;
  }
  return weighted / max(weights, vec3(1e-30));
}

// The share of the sun's own light at p (the ground's), 1 with no Moon.
vec3 eclipse_share_at(Atmosphere atmosphere, vec3 p) {
  if (u_moon.w <= 0.0) return vec3(1.0);
  return occluded_sun_fraction(u_sun_dir, atmosphere.sun_angular_radius, u_moon.xyz - p, u_moon.w);
}

// The sun's disk where the Moon does not hide it.
vec3 visible_sun_disk(Atmosphere atmosphere, vec3 camera, vec3 dir) {
  if (moon_hides_sun(camera, dir, u_moon.xyz, u_moon.w)) return vec3(0.0);
  return sun_disk_radiance(atmosphere, dot(dir, u_sun_dir));
}

// The scattering table and single Mie at (r, mu, mu_s, nu); with COMBINED,
// Mie's red only, the rest rebuilt from the ratio of the coefficients
// (Bruneton's default, which over-brightens the glow of a low sun).
vec3 scattering(Atmosphere atmosphere, float r, float mu, float mu_s, float nu, bool ground,
                out vec3 single_mie) {
#ifdef COMBINED
  vec4 combined = bruneton_scattering_lookup(atmosphere, u_scattering, r, mu, mu_s, nu, ground);
  single_mie = combined.r <= 0.0 ? vec3(0.0)
                                 : combined.rgb * combined.a / combined.r *
                                       (atmosphere.rayleigh_scattering.r / atmosphere.mie_scattering.r) *
                                       (atmosphere.mie_scattering / atmosphere.rayleigh_scattering);
  return combined.rgb;
#else
  single_mie = bruneton_scattering_lookup(atmosphere, u_single_mie, r, mu, mu_s, nu, ground).rgb;
  return bruneton_scattering_lookup(atmosphere, u_scattering, r, mu, mu_s, nu, ground).rgb;
#endif
}

vec3 with_phases(Atmosphere atmosphere, vec3 rayleigh, vec3 mie, float nu) {
  return rayleigh * rayleigh_phase(nu) + mie * mie_phase(atmosphere, nu);
}

// The camera moved to where the ray enters the atmosphere; false when it
// misses it.
bool enter(Atmosphere atmosphere, inout vec3 camera, vec3 dir) {
  float r = length(camera);
  if (r <= atmosphere.top_radius) return true;
  float t_near, t_far;
  if (!ray_sphere(camera, dir, atmosphere.top_radius, t_near, t_far) || t_far <= 0.0) return false;
  camera += max(t_near, 0.0) * dir;
  return true;
}

// Bruneton 2017, GetSkyRadiance: the light scattered toward the camera along
// the whole ray.
vec3 sky_radiance(Atmosphere atmosphere, vec3 camera, vec3 dir, out vec3 transmittance) {
  transmittance = vec3(1.0);
  if (!enter(atmosphere, camera, dir)) return vec3(0.0);
  float r = clamp(length(camera), atmosphere.bottom_radius, atmosphere.top_radius);
  float mu = clamp_cosine(dot(camera, dir) / r);
  float mu_s = clamp_cosine(dot(camera, u_sun_dir) / r);
  float nu = dot(dir, u_sun_dir);
  bool ground = ray_intersects_ground(atmosphere, r, mu);
  transmittance = ground ? vec3(0.0) : bruneton_transmittance_to_top(atmosphere, u_transmittance, r, mu);
  vec3 mie;
  vec3 rayleigh = scattering(atmosphere, r, mu, mu_s, nu, ground, mie);
  float t_ground_near, t_ground_far;
  float t_end = ground && ray_sphere(camera, dir, atmosphere.bottom_radius, t_ground_near,
                                     t_ground_far) ? t_ground_near : 3.0e38;
  return with_phases(atmosphere, rayleigh, mie, nu) *
         eclipse_share_along(atmosphere, camera, dir, t_end);
}

// Bruneton 2017, GetSkyRadianceToPoint: the light scattered toward the
// camera in front of the point at distance d along the ray, the difference
// of two lookups, for a given zenith cosine mu of the ray.
vec3 in_scattering(Atmosphere atmosphere, float r, float mu, float mu_s, float nu, float d,
                   out vec3 transmittance) {
  bool ground = ray_intersects_ground(atmosphere, r, mu);
  transmittance = bruneton_transmittance(atmosphere, u_transmittance, r, mu, d, ground);
  vec3 mie, mie_p;
  vec3 rayleigh = scattering(atmosphere, r, mu, mu_s, nu, ground, mie);
  float r_p = clamp(sqrt(d * d + 2.0 * r * mu * d + r * r), atmosphere.bottom_radius,
                    atmosphere.top_radius);
  float mu_p = clamp_cosine((r * mu + d) / r_p);
  float mu_s_p = clamp_cosine((r * mu_s + d * nu) / r_p);
  vec3 rayleigh_p = scattering(atmosphere, r_p, mu_p, mu_s_p, nu, ground, mie_p);
  rayleigh = max(rayleigh - transmittance * rayleigh_p, vec3(0.0));
  mie = max(mie - transmittance * mie_p, vec3(0.0));
  // Bruneton's: no single Mie from a sun below the horizon, where the
  // difference of two large lookups is noise.
  mie *= smoothstep(0.0, 0.01, mu_s);
  return with_phases(atmosphere, rayleigh, mie, nu);
}

// The view from the camera to a point: where it enters the atmosphere (r),
// its zenith cosine, the sun's, the cosine between them, the distance, and
// the zenith cosine of the ground's horizon from there.
struct ViewToPoint {
  bool in_atmosphere;
  float r, mu, mu_s, nu, d, mu_h;
};

ViewToPoint view_to_point(Atmosphere atmosphere, vec3 camera, vec3 point) {
  ViewToPoint v;
  vec3 dir = normalize(point - camera);
  v.in_atmosphere = enter(atmosphere, camera, dir);
  v.r = clamp(length(camera), atmosphere.bottom_radius, atmosphere.top_radius);
  v.mu = clamp_cosine(dot(camera, dir) / v.r);
  v.mu_s = clamp_cosine(dot(camera, u_sun_dir) / v.r);
  v.nu = dot(dir, u_sun_dir);
  v.d = length(point - camera);
  v.mu_h = -safe_sqrt(1.0 - (atmosphere.bottom_radius / v.r) * (atmosphere.bottom_radius / v.r));
  return v;
}

// The aerial perspective to a point. Near the horizon the two lookups fall
// on either side of the table's seam between rays that meet the ground and
// rays that do not, and their difference is not the air in between: a
// bright or dark line along the horizon (Bruneton's repository, issue 29).
// Within HORIZON_BLEND of the horizon's cosine (kHorizonPass's pixels) the
// result is the blend of the two evaluated just outside it, each
// consistent with itself.
bool near_horizon(ViewToPoint v) { return v.in_atmosphere && abs(v.mu - v.mu_h) < HORIZON_BLEND; }

vec3 sky_radiance_to_point(Atmosphere atmosphere, ViewToPoint v, out vec3 transmittance) {
  transmittance = vec3(1.0);
  if (!v.in_atmosphere) return vec3(0.0);
  float r = v.r, mu = v.mu, mu_s = v.mu_s, nu = v.nu, d = v.d, mu_h = v.mu_h;
#if PASS == kAllPass
  if (!near_horizon(v)) return in_scattering(atmosphere, r, mu, mu_s, nu, d, transmittance);
#elif PASS != kHorizonPass
  return in_scattering(atmosphere, r, mu, mu_s, nu, d, transmittance);
#endif
#if PASS == kHorizonPass || PASS == kAllPass
  vec3 t_below, t_above;
  vec3 below = in_scattering(atmosphere, r, mu_h - HORIZON_BLEND, mu_s, nu, d, t_below);
  vec3 above = in_scattering(atmosphere, r, mu_h + HORIZON_BLEND, mu_s, nu, d, t_above);
  float w = (mu - (mu_h - HORIZON_BLEND)) / (2.0 * HORIZON_BLEND);
  transmittance = mix(t_below, t_above, w);
  return mix(below, above, w);
#endif
}

// Bruneton 2017, GetSunAndSkyIrradiance on level ground at p: the sun's
// through the atmosphere and the sky's from the table.
vec3 ground_radiance_at(Atmosphere atmosphere, vec3 p) {
  float r = length(p);
  float mu_s = clamp_cosine(dot(p, u_sun_dir) / r);
  vec3 sun = atmosphere.solar_irradiance *
             bruneton_transmittance_to_sun(atmosphere, u_transmittance, r, mu_s) * max(mu_s, 0.0) *
             eclipse_share_at(atmosphere, p);
  vec3 sky = bruneton_irradiance(atmosphere, u_irradiance, r, mu_s);
  return atmosphere.ground_albedo / kPi * (sun + sky);
}

void main() {
  Atmosphere atmosphere = block_atmosphere();
  SkyPixel pixel = sky_pixel(atmosphere, u_depth, u_surface, v_ndc, u_ray_from_ndc, u_near, u_camera);
  float depth = pixel.depth;
  vec3 dir = pixel.dir;
  vec3 camera = pixel.camera;
  float t_ground_near, t_ground_far;
  bool hits_ground = ray_sphere(camera, dir, atmosphere.bottom_radius, t_ground_near, t_ground_far) &&
                     t_ground_near > 0.0;
  vec3 radiance, transmittance;
  float t_surface = pixel.t_surface;
  // The air in front of a surface ends at the bottom sphere (see
  // hillaire_sky.frag); where no surface was drawn, the sphere is the
  // ground, lit by the sun and the sky.
  float t = depth > 0.0 ? (hits_ground ? min(t_surface, t_ground_near) : t_surface) : t_ground_near;
#if PASS == kClassifyPass
  float t_top_near, t_top_far;
  bool in_atmosphere = ray_sphere(camera, dir, atmosphere.top_radius, t_top_near, t_top_far) &&
                       t_top_far > 0.0;
  bool meets_ground = depth > 0.0 || hits_ground;
#if CLASS == 1
  bool keep = meets_ground;
#elif CLASS == 2
  bool keep = meets_ground && near_horizon(view_to_point(atmosphere, camera, camera + t * dir));
#else
  bool keep = !meets_ground && !in_atmosphere;
#endif
  if (!keep) discard;
  radiance = visible_sun_disk(atmosphere, camera, dir);
#elif PASS == kAllPass
  // The classes of kClassifyPass, each pixel in its own branch.
  float t_top_near, t_top_far;
  bool in_atmosphere = ray_sphere(camera, dir, atmosphere.top_radius, t_top_near, t_top_far) &&
                       t_top_far > 0.0;
  if (depth > 0.0 || hits_ground) {
    vec3 surface = pixel.surface;
    if (depth == 0.0) surface = ground_radiance_at(atmosphere, camera + t_ground_near * dir);
    vec3 in_scatter = sky_radiance_to_point(
        atmosphere, view_to_point(atmosphere, camera, camera + t * dir), transmittance);
    in_scatter *= eclipse_share_along(atmosphere, camera, dir, t);
    radiance = in_scatter + transmittance * surface;
  } else if (!in_atmosphere) {
    radiance = visible_sun_disk(atmosphere, camera, dir);
  } else {
    radiance = sky_radiance(atmosphere, camera, dir, transmittance);
    radiance += transmittance * visible_sun_disk(atmosphere, camera, dir);
  }
#elif PASS == kAerialPass || PASS == kHorizonPass
  vec3 surface = pixel.surface;
  if (depth == 0.0) surface = ground_radiance_at(atmosphere, camera + t_ground_near * dir);
  vec3 in_scatter =
      sky_radiance_to_point(atmosphere, view_to_point(atmosphere, camera, camera + t * dir), transmittance);
  in_scatter *= eclipse_share_along(atmosphere, camera, dir, t);
  radiance = in_scatter + transmittance * surface;
#else
  radiance = sky_radiance(atmosphere, camera, dir, transmittance);
  radiance += transmittance * visible_sun_disk(atmosphere, camera, dir);
#endif
  // Within half-float range, so that a 16-bit target cannot overflow.
  o_radiance = vec4(min(radiance, vec3(6.0e4)), 1.0);
}
