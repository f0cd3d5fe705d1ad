// One star a point, at infinity (the far plane of the reversed-Z
// projection), its radiance dimmed by the air between the camera and
// space.
#include "atmosphere/shaders/surface_lighting.glsl"

layout(location = 0) in vec4 a_star;  // ICRF direction, radiance per unit solar irradiance

uniform mat3 u_view_from_icrf;
uniform mat3 u_body_from_icrf;
uniform mat4 u_clip_from_view;
uniform vec3 u_sun_at_1au;
uniform float u_scale;
uniform int u_has_atmosphere;
uniform vec3 u_atmo_scale;
uniform vec3 u_camera_atmo;

out vec3 v_radiance;

// Transmittance from p along d out to space: 1 for a ray that misses the
// atmosphere, 0 for one that meets the ground. From above the top the ray
// starts where it enters the top sphere.
vec3 transmittance_to_space(Atmosphere atmosphere, vec3 p, vec3 d) {
  float r = length(p);
  float mu = dot(p, d) / r;
  float top = atmosphere.top_radius;
  if (r > top) {
    float across = top * top - r * r * (1.0 - mu * mu);  // squared half chord
    if (mu >= 0.0 || across < 0.0) return vec3(1.0);
    p += (-r * mu - sqrt(across)) * d;
    r = top;
    mu = dot(p, d) / length(p);
  }
  r = max(r, atmosphere.bottom_radius);
  if (ray_intersects_ground(atmosphere, r, mu)) return vec3(0.0);
  return transmittance_to_top(atmosphere, r, mu, 16);
}

void main() {
  vec3 transmittance = vec3(1.0);
  if (u_has_atmosphere != 0) {
    vec3 dir_atmo = normalize(u_atmo_scale * (u_body_from_icrf * a_star.xyz));
    transmittance = transmittance_to_space(block_atmosphere(), u_camera_atmo, dir_atmo);
  }
  v_radiance = u_scale * a_star.w * u_sun_at_1au * transmittance;
  vec4 clip = u_clip_from_view * vec4(u_view_from_icrf * a_star.xyz, 1.0);
  gl_Position = vec4(clip.xy, 0.0, clip.w);
}
