// Evaluates Bruneton's table parameterisations (atmosphere/shaders/
// bruneton_functions.glsl) in float for the agreement test
// (tests/atmosphere/bruneton_functions_gl_test.cpp): one input
// (r, mu, mu_s, nu) per invocation, four vec4 of results.
#include "atmosphere/gpu/bruneton/bruneton_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform int u_count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  Atmosphere a = block_atmosphere();
  float r = inputs[i].x, mu = inputs[i].y, mu_s = inputs[i].z, nu = inputs[i].w;
  bool ground = ray_intersects_ground(a, r, mu);
  vec4 uvwz = bruneton_uvwz_from_r_mu_mu_s_nu(a, r, mu, mu_s, nu, ground);
  float r2, mu2, mu_s2, nu2;
  bool ground2;
  bruneton_r_mu_mu_s_nu_from_uvwz(a, uvwz, r2, mu2, mu_s2, nu2, ground2);
  float d = bruneton_distance_to_boundary(a, r, mu, ground);
  float unit = bruneton_unit_from_mu_s(a, mu_s);
  vec2 uv = bruneton_irradiance_uv_from_r_mu_s(a, r, mu_s);
  outputs[4 * i + 0] = uvwz;
  outputs[4 * i + 1] = vec4(r2, mu2, mu_s2, nu2);
  outputs[4 * i + 2] = vec4(ground ? 1.0 : 0.0, ground2 ? 1.0 : 0.0, d, unit);
  outputs[4 * i + 3] = vec4(uv, bruneton_mu_s_from_unit(a, unit),
                            bruneton_ray_sample(r, mu, d, 7, 20));
}
