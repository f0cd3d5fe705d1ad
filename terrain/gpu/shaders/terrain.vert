// Terrain tiles, placed relative to the eye: u_center_rel_eye is the tile
// centre minus the camera, formed in double on the CPU, and each vertex a
// float offset from that centre, so the sum is small wherever the camera
// is near, and float keeps it to a fraction of a millimetre.
#include "atmosphere/shaders/surface_lighting.glsl"

layout(location = 0) in vec3 a_offset;
layout(location = 1) in vec3 a_morph_delta;
layout(location = 2) in vec3 a_normal;
layout(location = 3) in vec4 a_albedo;

uniform vec3 u_center_rel_eye;
uniform mat3 u_view_from_body;
uniform mat4 u_clip_from_view;
uniform vec2 u_morph_range;  // eye distances where morphing to the parent starts and ends
uniform int u_has_atmosphere;
uniform vec3 u_atmo_scale;
uniform vec3 u_camera_atmo;
uniform vec3 u_sun_dir_atmo;
uniform int u_sky_light;  // 0: none (single scattering), 1: u_sky_irradiance, 2: an estimate
layout(binding = 15) uniform sampler2D u_sky_irradiance;

out vec3 v_normal_body;
out vec3 v_albedo;
out vec3 v_sun_transmittance;
out vec3 v_sky_irradiance;  // per unit solar irradiance

void main() {
  vec3 rel_eye = u_center_rel_eye + a_offset;
  // CDLOD (Strugar 2010): the morph factor grows with the distance to the
  // eye, the same for two tiles sharing an edge vertex, so neighbours agree.
  float d = length(rel_eye);
  float morph = clamp((d - u_morph_range.x) / (u_morph_range.y - u_morph_range.x), 0.0, 1.0);
  rel_eye += morph * a_morph_delta;
  gl_Position = u_clip_from_view * vec4(u_view_from_body * rel_eye, 1.0);
  v_normal_body = a_normal;
  v_albedo = a_albedo.rgb;
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
}
