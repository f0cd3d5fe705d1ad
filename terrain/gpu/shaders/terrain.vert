// Terrain tiles, placed relative to the eye: u_center_rel_eye is the tile
// centre minus the camera, formed in double on the CPU, and each vertex a
// float offset from that centre, so the sum is small wherever the camera
// is near, and float keeps it to a fraction of a millimetre.
#include "atmosphere/shaders/surface_lighting.glsl"

layout(location = 0) in vec3 a_offset;
layout(location = 1) in vec3 a_morph_delta;
layout(location = 2) in vec3 a_normal;
layout(location = 3) in vec4 a_albedo;
layout(location = 4) in vec4 a_horizon_0123;  // encoded horizon angles, directions 0 to 3
layout(location = 5) in vec4 a_horizon_4567;  // and 4 to 7
layout(location = 6) in vec2 a_sea;  // height over the sea, and its change to the parent grid's

uniform vec3 u_center_rel_eye;
uniform vec3 u_center_body;  // the tile's centre in float: enough for a vertex's up
uniform vec3 u_axis_i;       // the tile's grid directions at its centre, body frame
uniform vec3 u_axis_j;
uniform vec3 u_sun_dir_body;
uniform int u_shadows;  // 0: the horizon hides no sun
uniform mat3 u_view_from_body;
uniform mat4 u_clip_from_view;
uniform vec2 u_morph_range;  // eye distances where morphing to the parent starts and ends
uniform int u_has_atmosphere;
uniform vec3 u_atmo_scale;
uniform vec3 u_camera_atmo;
uniform vec3 u_sun_dir_atmo;
uniform int u_sky_light;  // 0: none (single scattering), 1: u_sky_irradiance, 2: an estimate
// The Moon before the sun (an eclipse): its centre less the eye, body
// frame, and its radius, metres; none while the radius is 0. And the
// sun's angular radius, radians.
uniform vec4 u_moon_rel_eye;
uniform float u_sun_angular_radius;
layout(binding = 15) uniform sampler2D u_sky_irradiance;

out vec3 v_normal_body;
out vec4 v_albedo;  // alpha: tile_mesh.cpp's pack_albedo
out vec3 v_position_body;
out float v_eye_distance;
out float v_over_sea;  // metres: negative at sea (over the datum where there is none)
out vec3 v_sun_transmittance;
out vec3 v_sky_irradiance;  // per unit solar irradiance
out float v_sun_over_horizon;  // the sun's elevation minus the horizon's in its azimuth, radians
out vec3 v_rel_eye;  // the vertex less the eye, body frame: the way it is seen (regolith, sea)
out vec3 v_tile_offset;  // from the tile's centre, unmorphed (the ground's detail)

const float kHalfPi = 1.5707963;

// horizon.cpp's decode_horizon, from the byte normalised to [0, 1].
float decode_horizon(float v) {
  float q = 2.0 * v - 1.0;
  return sign(q) * q * q * kHalfPi;
}

// How far the sun stands above this vertex's horizon, in the directions
// of its tile's grid (horizon.h): the horizon in the sun's azimuth is
// interpolated between the two grid directions beside it.
float sun_over_horizon(vec3 position_body) {
  vec3 up = normalize(position_body);
  float elevation = asin(clamp(dot(u_sun_dir_body, up), -1.0, 1.0));
  vec3 along_i = u_axis_i - dot(u_axis_i, up) * up;
  vec3 along_j = u_axis_j - dot(u_axis_j, up) * up;
  float azimuth = atan(dot(u_sun_dir_body, along_j) / length(along_j),
                       dot(u_sun_dir_body, along_i) / length(along_i));
  float sector = mod(azimuth / (0.25 * 3.14159265), 8.0);
  int k0 = int(floor(sector)) % 8, k1 = (k0 + 1) % 8;
  float horizon[8] = float[8](a_horizon_0123.x, a_horizon_0123.y, a_horizon_0123.z,
                              a_horizon_0123.w, a_horizon_4567.x, a_horizon_4567.y,
                              a_horizon_4567.z, a_horizon_4567.w);
  float h = mix(decode_horizon(horizon[k0]), decode_horizon(horizon[k1]), fract(sector));
  return elevation - h;
}

void main() {
  vec3 rel_eye = u_center_rel_eye + a_offset;
  // CDLOD (Strugar 2010): the morph factor grows with the distance to the
  // eye, the same for two tiles sharing an edge vertex, so neighbours agree.
  float d = length(rel_eye);
  float morph = clamp((d - u_morph_range.x) / (u_morph_range.y - u_morph_range.x), 0.0, 1.0);
  rel_eye += morph * a_morph_delta;
  gl_Position = u_clip_from_view * vec4(u_view_from_body * rel_eye, 1.0);
  v_normal_body = a_normal;
  v_albedo = a_albedo;
  v_position_body = u_center_body + a_offset;
  v_eye_distance = d;
  v_rel_eye = rel_eye;
  v_tile_offset = a_offset;
  v_over_sea = a_sea.x + morph * a_sea.y;
#ifndef TERRAIN_COVERAGE  // the coverage pass (terrain_coverage.frag) takes no light
  v_sun_over_horizon = u_shadows != 0 ? sun_over_horizon(u_center_body + a_offset) : kHalfPi;
  v_sun_transmittance = vec3(1.0);
  v_sky_irradiance = vec3(0.0);
  if (u_has_atmosphere != 0) {
    vec3 p = u_camera_atmo + u_atmo_scale * rel_eye;
    v_sun_transmittance = surface_sun_transmittance(block_atmosphere(), p, u_sun_dir_atmo);
    if (u_sky_light == 1) {
      v_sky_irradiance = surface_sky_irradiance(u_sky_irradiance, p, a_normal, u_sun_dir_atmo);
    } else if (u_sky_light == 2) {
      v_sky_irradiance =
          surface_sky_irradiance_estimate(p, a_normal, u_sun_dir_atmo, v_sun_transmittance);
    }
  }
  // In an eclipse the sun's light on the ground, direct and glint, is the
  // visible share of its disk here (occluded_sun.glsl; the umbra is 200 km
  // wide, the penumbra thousands: a vertex's share serves its triangle).
  // The estimate above is taken before it, from the air's loss of the
  // whole sun.
  if (u_moon_rel_eye.w > 0.0) {
    v_sun_transmittance *= occluded_sun_fraction(u_sun_dir_body, u_sun_angular_radius,
                                                 u_moon_rel_eye.xyz - rel_eye, u_moon_rel_eye.w);
    // The sky's light here comes from the air around and above it, lit by
    // the share of the sun there: the technique's table (which knows one
    // sun for the whole sky) times the mean share at the point a scale
    // height (8 km) above and at six points 40 km around that (the sky's
    // irradiance comes mostly from elevations over 15 degrees). In the
    // partial phase, whose share changes over thousands of kilometres,
    // that is the share here; deep in the umbra, no sky light, where the
    // ground truth's is a hundredth of the partial phase's at a tenth of
    // the sun.
    vec3 up = normalize(u_center_body + a_offset);
    vec3 east = normalize(cross(abs(up.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0), up));
    vec3 north = cross(up, east);
    vec3 above = rel_eye + 8000.0 * up;
    vec3 sky_share = occluded_sun_fraction(u_sun_dir_body, u_sun_angular_radius,
                                           u_moon_rel_eye.xyz - above, u_moon_rel_eye.w);
    for (int k = 0; k < 6; ++k) {
      float a = float(k) * 1.0471976;  // pi / 3
      vec3 around = above + 40000.0 * (cos(a) * east + sin(a) * north);
      sky_share += occluded_sun_fraction(u_sun_dir_body, u_sun_angular_radius,
                                         u_moon_rel_eye.xyz - around, u_moon_rel_eye.w);
    }
    v_sky_irradiance *= sky_share / 7.0;
  }
#endif
}
