// The cloud layer over the frame's radiance (cloud_march: what the clouds
// add to a pixel and their transmittance), marched along a pixel's
// view ray through the layer's shell (from the ground, inside it and from
// orbit, one march: no switch between views). Each sample is lit by the
// sun through the air (the shared transmittance, and the planet's shadow)
// and the clouds toward the sun, with multiple scattering by Wrenninge et
// al. 2013's octaves (cloud_octaves in cloud_scattering.glsl, a = 1/4:
// with a = 1/2 a cumulus of optical depth 30 toward the sun sends back a
// fifth of what a = 1/4 does, and looks grey from orbit), plus the sky's
// light as an isotropic ambient. Then the air in front of the clouds
// (aerial perspective) is marched to their transmittance-weighted distance:
// out = T_air L_clouds + (1 - T_clouds) S_air, blended over the radiance
// behind as out + T_clouds * behind (GL_ONE, GL_SRC_ALPHA). Included by
// clouds_march.frag (at the pass's resolution) and, through
// cloud_upsample.glsl, by the passes that bring it to full resolution.
#include "atmosphere/shaders/atmosphere_block.glsl"

// The sun's light through the air by quadrature, as the terrain's lighting
// takes it (surface_lighting.glsl): 8 steps.
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_to_top(atmosphere, r, mu, 8);
}
#include "atmosphere/shaders/sunlight.glsl"
#include "atmosphere/shaders/surface_lighting.glsl"
#include "atmosphere/gpu/sky_pixel.glsl"
#include "clouds/shaders/cloud_definitions.glsl"
#include "clouds/shaders/cloud_noise.glsl"
#include "clouds/shaders/cloud_density.glsl"
#include "clouds/shaders/cloud_phase.glsl"
#include "clouds/shaders/cloud_scattering.glsl"

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_surface;
layout(binding = 2) uniform sampler2D u_sky_irradiance;
uniform bool u_has_sky_irradiance;
uniform vec3 u_camera;  // atmosphere space, metres
uniform mat3 u_ray_from_ndc;
uniform vec3 u_sun_dir;
uniform float u_near;
uniform vec4 u_layer[3];  // CloudLayer's twelve fields in order
uniform int u_steps;        // samples along the view ray in the layer
uniform int u_light_steps;  // samples toward the sun from each
uniform int u_octaves;      // Wrenninge's octaves (1: single scattering)
uniform ivec2 u_size;       // the full-resolution target's
uniform int u_factor;       // full-resolution pixels per marched one, each way

// The centre of a full-resolution pixel in NDC.
vec2 cloud_pixel_ndc(ivec2 pixel) { return (vec2(pixel) + 0.5) / vec2(u_size) * 2.0 - 1.0; }

// The full-resolution pixel that marched pixel `low` stands for: the one
// at its block's centre (the upper right of the middle four), inside the
// image.
ivec2 cloud_source_pixel(ivec2 low) { return min(low * u_factor + u_factor / 2, u_size - 1); }

CloudLayer uniform_layer() {
  return CloudLayer(u_layer[0].x, u_layer[0].y, u_layer[0].z, u_layer[0].w, u_layer[1].x,
                    u_layer[1].y, u_layer[1].z, u_layer[1].w, u_layer[2].x, u_layer[2].y,
                    u_layer[2].z, u_layer[2].w);
}

// The clouds' optical depth toward the sun from p, across the layer's
// thickness in u_light_steps steps (a low sun crosses more of it, up to 4
// thicknesses): the shapes under p's weather, without their erosion, which
// a few kilometres of march toward the sun would not resolve.
float optical_depth_to_sun(CloudLayer layer, vec3 p, vec2 weather) {
  float t_near, t_far;
  float span = ray_sphere(p, u_sun_dir, layer.top_radius, t_near, t_far) ? max(t_far, 0.0) : 0.0;
  span = min(span, 4.0 * (layer.top_radius - layer.bottom_radius));
  float ds = span / float(u_light_steps);
  float depth = 0.0;
  for (int i = 0; i < u_light_steps; ++i) {
    depth += cloud_shape_density(layer, p + ((float(i) + 0.5) * ds) * u_sun_dir, weather);
  }
  return depth * layer.extinction * ds;
}

// Single scattering by the air from `origin` along dir over `len`, and its
// transmittance: the aerial perspective in front of the clouds. Samples
// crowd toward the camera (s = u^2), where the air is densest along a
// rising ray: spread evenly over a grazing way of hundreds of kilometres,
// they would step over most of the air near the camera.
void air_segment(Atmosphere atmosphere, vec3 origin, vec3 dir, float len, out vec3 inscatter,
                 out vec3 transmittance) {
  const int kSteps = 12;
  float nu = dot(dir, u_sun_dir);
  float phase_r = rayleigh_phase(nu);
  float phase_m = mie_phase(atmosphere, nu);
  vec3 depth = vec3(0.0);
  inscatter = vec3(0.0);
  for (int i = 0; i < kSteps; ++i) {
    float u0 = float(i) / float(kSteps), u1 = float(i + 1) / float(kSteps);
    float u = 0.5 * (u0 + u1);
    float ds = len * (u1 * u1 - u0 * u0);
    vec3 p = origin + (len * u * u) * dir;
    float r = length(p);
    float altitude = r - atmosphere.bottom_radius;
    vec3 extinction = extinction_at(atmosphere, altitude);
    vec3 t_camera = exp(-(depth + 0.5 * extinction * ds));
    depth += extinction * ds;
    vec3 scattering =
        atmosphere.rayleigh_scattering * profile_density(atmosphere.rayleigh_density, altitude) *
            phase_r +
        atmosphere.mie_scattering * profile_density(atmosphere.mie_density, altitude) * phase_m;
    inscatter += t_camera * sun_visibility(atmosphere, max(r, atmosphere.bottom_radius),
                                           dot(p, u_sun_dir) / r) *
                 scattering * ds;
  }
  inscatter *= atmosphere.solar_irradiance;
  transmittance = exp(-depth);
}

// The weather at kWeatherNodes points spread over a ray's way through the
// layer as its samples are (s = u^2), and linearly between: it varies over
// the weather's cells (250 km for Earth), and taken at each of 32 samples
// it was 5 of a sample's 22 value noises.
const int kWeatherNodes = 5;

// A pixel's view ray and its stretches in the layer's shell before the
// surface: the first from t_enter, and a second from t_again.
struct CloudRay {
  SkyPixel pixel;
  float t_enter, first;   // the first stretch's start and length
  float t_again, second;  // the second's, 0 without one
};

// Full-resolution pixel `at`'s ray; false where it meets no cloud layer
// before its surface. The passes discard those pixels (over a target
// cleared to no clouds) rather than return early: llvmpipe runs a block
// of pixels in lockstep and skips the march only where a whole block has
// been discarded.
bool cloud_ray(ivec2 at, out CloudRay ray) {
  Atmosphere atmosphere = block_atmosphere();
  CloudLayer layer = uniform_layer();
  ray.pixel = sky_pixel_at(atmosphere, u_depth, u_surface, at, cloud_pixel_ndc(at),
                           u_ray_from_ndc, u_near, u_camera);
  SkyPixel pixel = ray.pixel;
  // The ray's stretches in the layer's shell: the first (ray_shell), and
  // for a ray that dips below the base from inside the layer and misses
  // the ground, the second where it comes back up: seen from just below
  // the base that stretch is the first, so leaving it out made the
  // horizon jump as the camera crossed the base.
  float t_enter, t_exit;
  if (!ray_shell(pixel.camera, pixel.dir, layer.bottom_radius, layer.top_radius, t_enter, t_exit)) {
    return false;
  }
  float t_again = 0.0, t_again_exit = 0.0;
  float base_near, base_far, top_near, top_far;
  if (ray_sphere(pixel.camera, pixel.dir, layer.bottom_radius, base_near, base_far) &&
      base_near > t_enter &&
      ray_sphere(pixel.camera, pixel.dir, layer.top_radius, top_near, top_far)) {
    t_again = base_far;
    t_again_exit = min(top_far, pixel.t_surface);
  }
  t_exit = min(t_exit, pixel.t_surface);
  ray.t_enter = t_enter;
  ray.first = max(t_exit - t_enter, 0.0);
  ray.t_again = t_again;
  ray.second = max(t_again_exit - t_again, 0.0);
  return ray.first + ray.second > 0.0;
}

// What decides a pixel's clouds besides its direction (x, y), for the
// blend to full resolution (cloud_upsample.glsl): the length of its way
// through the layer before its surface (x) and where the march ends (y):
// in the open sky (-1, along its own direction over the lifted horizon);
// at a surface below the layer's base (0), whatever the surface's
// distance, as a ray that met it had left the layer for good; or at a
// surface in or above the layer, its distance. (0, 0): no layer.
vec2 cloud_ray_key(CloudRay ray) {
  if (ray.pixel.depth == 0.0) return vec2(ray.first + ray.second, -1.0);
  vec3 surface = ray.pixel.camera + ray.pixel.t_surface * ray.pixel.dir;
  return vec2(ray.first + ray.second,
              length(surface) < uniform_layer().bottom_radius ? 0.0 : ray.pixel.t_surface);
}

// What the clouds add to full-resolution pixel `at` (rgb) and their
// transmittance (a), along its ray (cloud_ray).
vec4 cloud_march(ivec2 at, CloudRay ray) {
  Atmosphere atmosphere = block_atmosphere();
  CloudLayer layer = uniform_layer();
  SkyPixel pixel = ray.pixel;
  float t_enter = ray.t_enter, t_again = ray.t_again;
  float first = ray.first, second = ray.second;
  float segment = first + second;
  // Each stretch rebased at its entry, as the sky's marches are: far away
  // the camera's coordinates have too few bits for the steps. Samples
  // crowd near the entry (s = u^2 over both stretches end to end), where a
  // grazing stretch is nearest; a fixed offset per pixel (the clouds' own
  // hash of the pixel: interleaved gradient noise left diagonal stripes on
  // the cloud tops) turns banding into a fine, deterministic grain.
  vec3 origin = pixel.camera + t_enter * pixel.dir;
  vec3 origin_again = pixel.camera + t_again * pixel.dir;
  float jitter = float(cloud_hash(uvec3(uvec2(at), 7u)) >> 8u) / 16777216.0;
  float nu = dot(pixel.dir, u_sun_dir);
  float phase = cloud_phase(layer.droplet_diameter_um, nu);
  vec3 sun = atmosphere.solar_irradiance;
  // The sun through the air (and the planet's shadow) at the start, the
  // middle and the end of the ray's way through the layer, and linearly
  // between: a grazing way at sunset runs hundreds of kilometres, from
  // sunlight into the planet's shadow.
  vec3 sun_at[3];
  for (int k = 0; k < 3; ++k) {
    float s = 0.5 * float(k) * segment;
    vec3 q = s < first || second <= 0.0 ? origin + min(s, first) * pixel.dir
                                         : origin_again + (s - first) * pixel.dir;
    sun_at[k] = sun * sun_visibility(atmosphere, length(q), dot(q, u_sun_dir) / length(q));
  }
  vec2 weather_at[kWeatherNodes];
  for (int k = 0; k < kWeatherNodes; ++k) {
    float u = float(k) / float(kWeatherNodes - 1);
    float s = segment * u * u;
    vec3 q = s < first || second <= 0.0 ? origin + min(s, first) * pixel.dir
                                         : origin_again + (s - first) * pixel.dir;
    weather_at[k] = cloud_weather(layer, q);
  }
  vec3 radiance = vec3(0.0);
  float transmittance = 1.0;
  float weighted_t = 0.0, weight = 0.0;
  float s_prev = 0.0;
  for (int i = 0; i < u_steps; ++i) {
    float u = (float(i) + jitter) / float(u_steps);
    float s = segment * u * u;
    float u_next = (float(i) + 1.0) / float(u_steps);
    float ds = segment * u_next * u_next - s_prev;
    s_prev = segment * u_next * u_next;
    bool again = s >= first;
    vec3 p = again ? origin_again + (s - first) * pixel.dir : origin + s * pixel.dir;
    float node = u * float(kWeatherNodes - 1);
    int n = min(int(node), kWeatherNodes - 2);
    vec2 weather = mix(weather_at[n], weather_at[n + 1], node - float(n));
    float density = cloud_eroded_density(layer, p, cloud_shape_density(layer, p, weather));
    if (density <= 0.0) continue;
    float extinction = layer.extinction * density;
    float r = length(p);
    float w = 2.0 * s / segment;
    vec3 sunlight = w < 1.0 ? mix(sun_at[0], sun_at[1], w) : mix(sun_at[1], sun_at[2], w - 1.0);
    float tau_sun = optical_depth_to_sun(layer, p, weather);
    float octaves = cloud_octaves(phase, tau_sun, dot(p, u_sun_dir) / r, u_octaves);
    // The sky's light: its irradiance on level ground at p as an isotropic
    // radiance E / pi from the upper half of the sphere (half of it
    // scattered toward any direction), dimmer toward the layer's base,
    // which the clouds above shade.
    float h = (r - layer.bottom_radius) / (layer.top_radius - layer.bottom_radius);
    vec3 sky = u_has_sky_irradiance
                   ? surface_sky_irradiance(u_sky_irradiance, p, p, u_sun_dir)
                   : surface_sky_irradiance_estimate(p, p, u_sun_dir, sunlight / sun);
    vec3 ambient = sun * sky * (0.5 * mix(0.4, 1.0, h) / kPi);
    vec3 source = layer.albedo * (sunlight * octaves + ambient);
    // Hillaire 2016's integral over the step: the source times
    // (1 - exp(-extinction ds)) / extinction, exact for a constant source.
    float step_transmittance = exp(-extinction * ds);
    radiance += transmittance * source * (1.0 - step_transmittance);
    weighted_t +=
        transmittance * (1.0 - step_transmittance) * (again ? t_again + s - first : t_enter + s);
    weight += transmittance * (1.0 - step_transmittance);
    transmittance *= step_transmittance;
    if (transmittance < 1e-3) break;
  }
  if (weight <= 0.0) return vec4(0.0, 0.0, 0.0, 1.0);
  vec3 inscatter, air;
  air_segment(atmosphere, pixel.camera, pixel.dir, weighted_t / weight, inscatter, air);
  return vec4(air * radiance + (1.0 - transmittance) * inscatter, transmittance);
}
