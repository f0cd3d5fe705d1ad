// The sky's irradiance on level ground per unit solar irradiance, from the
// irradiance table at the bottom of the atmosphere, as the one row over the
// sun's zenith cosine that surfaces read (AtmosphereTechnique::
// ground_irradiance; surface_lighting.glsl).
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D u_irradiance;
layout(rgba32f, binding = 0) uniform writeonly image2D u_output;
uniform int u_width;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_width) return;
  Atmosphere atmosphere = block_atmosphere();
  float mu_s = mu_s_from_sky_irradiance_u(float(i) / float(u_width - 1));
  vec3 sky = bruneton_irradiance(atmosphere, u_irradiance, atmosphere.bottom_radius, mu_s);
  imageStore(u_output, ivec2(i, 0), vec4(sky / atmosphere.solar_irradiance, 1.0));
}
