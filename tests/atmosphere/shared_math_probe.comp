// Evaluates the shared atmosphere functions in float for the agreement test
// (tests/atmosphere/shared_math_gl_test.cpp): one input (r, mu, H, nu) per
// invocation, four vec4 of results.
#include "atmosphere/shaders/atmosphere_block.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform vec4 u_shell;  // bottom radius, top radius, Mie g, Henyey-Greenstein (1) or not (0)
uniform int u_count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  Atmosphere a;
  a.bottom_radius = u_shell.x;
  a.top_radius = u_shell.y;
  a.mie_g = u_shell.z;
  a.mie_phase_hg = u_shell.w;
  float r = inputs[i].x, mu = inputs[i].y, H = inputs[i].z, nu = inputs[i].w;
  outputs[4 * i + 0] = vec4(distance_to_top_boundary(a, r, mu),
                            distance_to_bottom_boundary(a, r, mu),
                            exponential_optical_depth_to_top(a, H, r, mu),
                            erfcx(abs(nu) * 10.0));
  outputs[4 * i + 1] = vec4(rayleigh_phase(nu), henyey_greenstein_phase(a.mie_g, nu),
                            cornette_shanks_phase(a.mie_g, nu), isotropic_phase());
  vec2 size = vec2(256.0, 64.0);
  vec2 uv = transmittance_uv_from_r_mu(a, r, mu, size);
  vec2 r_mu = transmittance_r_mu_from_uv(a, uv, size);
  outputs[4 * i + 2] = vec4(uv, r_mu);
  float t0, t1;
  vec3 o = vec3(0.0, 0.0, r);
  vec3 d = vec3(sqrt(max(1.0 - mu * mu, 0.0)), 0.0, mu);
  bool hit = ray_shell(o, d, a.bottom_radius, a.top_radius, t0, t1);
  outputs[4 * i + 3] = vec4(hit ? 1.0 : 0.0, t0, t1, mie_phase(a, nu));
}
