// Terrain tiles, placed relative to the eye: u_center_rel_eye is the tile
// centre minus the camera, formed in double on the CPU, and each vertex a
// float offset from that centre, so the sum is small wherever the camera
// is near, and float keeps it to a fraction of a millimetre.
#include "atmosphere/shaders/atmosphere_block.glsl"

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
uniform int u_has_sky_irradiance;
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
    Atmosphere atmosphere = block_atmosphere();
    vec3 p = u_camera_atmo + u_atmo_scale * rel_eye;
    float r = max(length(p), atmosphere.bottom_radius);
    vec3 up = p / length(p);
    float mu_s = dot(up, u_sun_dir_atmo);
    v_sun_transmittance = ray_intersects_ground(atmosphere, r, mu_s)
                              ? vec3(0.0)
                              : transmittance_to_top(atmosphere, r, mu_s, 16);
    // Sky irradiance, single scattering and isotropic: of the sunlight the
    // beam loses on its way down to r (1 - T, scattering taken for all of
    // the extinction), half goes down, spread over the sky; a horizontal
    // surface receives mu_s of the beam's flux, a tilted one the visible
    // fraction (1 + n.up) / 2 of the sky. A rough but documented ambient
    // that vanishes at night and reddens with the sun (cf. Bruneton and
    // Neyret 2008, eq. 15, for the full integral).
    float sky_fraction = 0.5 * (1.0 + dot(normalize(a_normal), up));
    v_sky_irradiance = 0.5 * max(mu_s, 0.0) * (vec3(1.0) - v_sun_transmittance) * sky_fraction;
    // Better, where the technique has it: the sky's irradiance on level
    // ground summed over all orders of scattering, times the same fraction.
    if (u_has_sky_irradiance != 0) {
      float n = float(textureSize(u_sky_irradiance, 0).x);
      float u = texture_coord_from_unit_range(sky_irradiance_u_from_mu_s(mu_s), n);
      v_sky_irradiance = texture(u_sky_irradiance, vec2(u, 0.5)).rgb * sky_fraction;
    }
  }
}
