// Lambertian ground lit by the sun through the atmosphere. Radiance leaving
// the surface toward the camera; the atmosphere pass adds what lies between.
#include "atmosphere/shaders/atmosphere_block.glsl"

in vec3 v_normal_body;
in vec3 v_sun_transmittance;
layout(location = 0) out vec4 o_radiance;

uniform vec3 u_sun_dir_body;
uniform float u_albedo;
uniform int u_has_atmosphere;

void main() {
  vec3 n = normalize(v_normal_body);
  float cos_sun = max(dot(n, u_sun_dir_body), 0.0);
  vec3 irradiance = u_has_atmosphere != 0 ? u_solar_irradiance.rgb : vec3(1.0);
  o_radiance = vec4(u_albedo / kPi * irradiance * v_sun_transmittance * cos_sun, 1.0);
}
