// One order of scattering for the multiple-scattering LUT (see "Scattering
// orders" in hillaire_functions.glsl): rows 0-31 hold J_n over (mu_s, r),
// row 32 the ground's irradiance E_n over mu_s. The first order comes from
// the sun, every later one from the order before (u_previous_order and
// u_previous_ground).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_order;
layout(rgba32f, binding = 1) uniform writeonly image2D u_ground;

uniform bool u_first_order;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int n = kMultipleScatteringLutSize;
  if (texel.x >= n || texel.y > n) return;
  Atmosphere atmosphere = block_atmosphere();
  int source_kind = u_first_order ? kSourceFirstOrder : kSourceNextOrder;
  float u = (float(texel.x) + 0.5) / float(n);
  if (texel.y == n) {
    float r, mu_s;
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, 0.5 / float(n), r, mu_s);
    vec3 e = gather_order(atmosphere, ground_gather_radius(atmosphere), mu_s, source_kind, true);
    imageStore(u_ground, ivec2(texel.x, 0), vec4(e, 1.0));
  } else {
    float r, mu_s;
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, (float(texel.y) + 0.5) / float(n), r,
                                           mu_s);
    imageStore(u_order, texel, vec4(gather_order(atmosphere, r, mu_s, source_kind, false), 1.0));
  }
}
