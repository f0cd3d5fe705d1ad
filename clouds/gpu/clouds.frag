// The cloud layer over the frame's radiance, marched along each pixel's
// view ray through the layer's shell (from the ground, inside it and from
// orbit, one march: no switch between views). Each sample is lit by the
// sun through the air (the shared transmittance, and the planet's shadow)
// and the clouds toward the sun, with multiple scattering by Wrenninge et
// al. 2013's octaves ("Production Volume Rendering", SIGGRAPH course,
// sec. 5.4: octave i takes a^i of the optical depth toward the sun, b^i of
// the light and a phase c^i as eccentric; a = 1/4, b = c = 1/2, within
// their a <= b that keeps energy: with a = 1/2 a cumulus of optical depth
// 30 toward the sun sends back a fifth of what a = 1/4 does, and looks
// grey from orbit), plus the sky's
// light as an isotropic ambient. Then the air in front of the clouds
// (aerial perspective) is marched to their transmittance-weighted distance:
// out = T_air L_clouds + (1 - T_clouds) S_air, blended over the radiance
// behind as out + T_clouds * behind (GL_ONE, GL_SRC_ALPHA).
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

in vec2 v_ndc;
layout(location = 0) out vec4 o_radiance;

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

void main() {
  o_radiance = vec4(0.0, 0.0, 0.0, 1.0);
  Atmosphere atmosphere = block_atmosphere();
  CloudLayer layer = uniform_layer();
  SkyPixel pixel = sky_pixel(atmosphere, u_depth, u_surface, v_ndc, u_ray_from_ndc, u_near,
                             u_camera);
  // The ray's stretches in the layer's shell: the first (ray_shell), and
  // for a ray that dips below the base from inside the layer and misses
  // the ground, the second where it comes back up: seen from just below
  // the base that stretch is the first, so leaving it out made the
  // horizon jump as the camera crossed the base.
  float t_enter, t_exit;
  if (!ray_shell(pixel.camera, pixel.dir, layer.bottom_radius, layer.top_radius, t_enter, t_exit)) {
    return;
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
  float first = max(t_exit - t_enter, 0.0);
  float second = max(t_again_exit - t_again, 0.0);
  float segment = first + second;
  if (segment <= 0.0) return;
  // Each stretch rebased at its entry, as the sky's marches are: far away
  // the camera's coordinates have too few bits for the steps. Samples
  // crowd near the entry (s = u^2 over both stretches end to end), where a
  // grazing stretch is nearest; a fixed offset per pixel (the clouds' own
  // hash of the pixel: interleaved gradient noise left diagonal stripes on
  // the cloud tops) turns banding into a fine, deterministic grain.
  vec3 origin = pixel.camera + t_enter * pixel.dir;
  vec3 origin_again = pixel.camera + t_again * pixel.dir;
  float jitter = float(cloud_hash(uvec3(uvec2(gl_FragCoord.xy), 7u)) >> 8u) / 16777216.0;
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
    vec2 weather = cloud_weather(layer, p);
    float density = cloud_eroded_density(layer, p, cloud_shape_density(layer, p, weather));
    if (density <= 0.0) continue;
    float extinction = layer.extinction * density;
    float r = length(p);
    float w = 2.0 * s / segment;
    vec3 sunlight = w < 1.0 ? mix(sun_at[0], sun_at[1], w) : mix(sun_at[1], sun_at[2], w - 1.0);
    float tau_sun = optical_depth_to_sun(layer, p, weather);
    // Wrenninge's octaves.
    float octaves = 0.0, b = 1.0, a = 1.0;
    for (int k = 0; k < u_octaves; ++k) {
      octaves += b * mix(isotropic_phase(), phase, b) * exp(-a * tau_sun);
      b *= 0.5;
      a *= 0.25;
    }
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
  if (weight <= 0.0) return;
  vec3 inscatter, air;
  air_segment(atmosphere, pixel.camera, pixel.dir, weighted_t / weight, inscatter, air);
  o_radiance = vec4(air * radiance + (1.0 - transmittance) * inscatter, transmittance);
}
