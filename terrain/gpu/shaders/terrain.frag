// Lambertian terrain lit by the sun through the atmosphere plus the sky's
// ambient: the radiance leaving the ground toward the camera. The
// atmosphere pass adds what lies between (aerial perspective).
#include "atmosphere/shaders/surface_lighting.glsl"

in vec3 v_normal_body;
in vec3 v_albedo;
in vec3 v_sun_transmittance;
in vec3 v_sky_irradiance;
layout(location = 0) out vec4 o_radiance;

uniform vec3 u_sun_dir_body;
uniform vec3 u_sun_irradiance;

void main() {
  vec3 n = normalize(v_normal_body);
  float cos_sun = max(dot(n, u_sun_dir_body), 0.0);
  vec3 irradiance = u_sun_irradiance * (v_sun_transmittance * cos_sun + v_sky_irradiance);
  o_radiance = vec4(v_albedo / kPi * irradiance, 1.0);
}
