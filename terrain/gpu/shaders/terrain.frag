// Lambertian terrain lit by the sun through the atmosphere, where the
// terrain's horizon does not hide it, plus the sky's ambient: the radiance
// leaving the ground toward the camera. The atmosphere pass adds what lies
// between (aerial perspective).
#include "atmosphere/shaders/surface_lighting.glsl"

in vec3 v_normal_body;
in vec3 v_albedo;
in vec3 v_sun_transmittance;
in vec3 v_sky_irradiance;
in float v_sun_over_horizon;
layout(location = 0) out vec4 o_radiance;

uniform vec3 u_sun_dir_body;
uniform vec3 u_sun_irradiance;
// Half the width of a shadow's edge in sun elevation, radians: the sun's
// disc, or the horizon's coding where that is coarser.
uniform float u_penumbra;

void main() {
  vec3 n = normalize(v_normal_body);
  // The share of the sun's disc above the horizon: interpolated per
  // fragment, the shadow's edge falls between vertices.
  float sun_visible = smoothstep(-u_penumbra, u_penumbra, v_sun_over_horizon);
  float cos_sun = max(dot(n, u_sun_dir_body), 0.0) * sun_visible;
  vec3 irradiance = u_sun_irradiance * (v_sun_transmittance * cos_sun + v_sky_irradiance);
  o_radiance = vec4(v_albedo / kPi * irradiance, 1.0);
}
