// The planet's surface, placed relative to the eye: u_center_rel_eye is the
// patch centre minus the camera, formed in double on the CPU, and the
// vertex is a float offset from that centre.
#include "atmosphere/shaders/atmosphere_block.glsl"

layout(location = 0) in vec3 a_offset;
layout(location = 1) in vec3 a_normal;

uniform vec3 u_center_rel_eye;
uniform mat3 u_view_from_body;
uniform mat4 u_clip_from_view;
uniform int u_has_atmosphere;
uniform vec3 u_atmo_scale;
uniform vec3 u_camera_atmo;
uniform vec3 u_sun_dir_atmo;

out vec3 v_normal_body;
out vec3 v_sun_transmittance;

void main() {
  vec3 rel_eye = u_center_rel_eye + a_offset;
  gl_Position = u_clip_from_view * vec4(u_view_from_body * rel_eye, 1.0);
  v_normal_body = a_normal;
  v_sun_transmittance = vec3(1.0);
  if (u_has_atmosphere != 0) {
    Atmosphere atmosphere = block_atmosphere();
    vec3 p = u_camera_atmo + u_atmo_scale * rel_eye;
    float r = max(length(p), atmosphere.bottom_radius);
    float mu_s = dot(p, u_sun_dir_atmo) / length(p);
    v_sun_transmittance = ray_intersects_ground(atmosphere, r, mu_s)
                              ? vec3(0.0)
                              : transmittance_to_top(atmosphere, r, mu_s, 16);
  }
}
