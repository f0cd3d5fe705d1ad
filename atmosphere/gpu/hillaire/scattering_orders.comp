// One order of scattering for the multiple-scattering LUT (see "Scattering
// orders" in hillaire_functions.glsl): rows 0 to n-1 hold the order's mean
// radiance J_n and its moment (kFieldParts parts side by side) over
// (mu_s, r), row n the ground's irradiance E_n over mu_s. The first order
// comes from the sun, every later one from the order before
// (u_previous_order, the same layout).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_order;

uniform bool u_first_order;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int n = kMultipleScatteringLutSize;
  if (texel.x >= n || texel.y > n) return;
  Atmosphere atmosphere = block_atmosphere();
  int source_kind = u_first_order ? kSourceFirstOrder : kSourceNextOrder;
  float u = (float(texel.x) + 0.5) / float(n);
  float r, mu_s;
  vec3 moment_up, moment_sun;
  if (texel.y == n) {
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, 0.5 / float(n), r, mu_s);
    vec3 e = gather_order(atmosphere, ground_gather_radius(atmosphere), mu_s, source_kind, true,
                          moment_up, moment_sun);
    imageStore(u_order, texel, vec4(e, 1.0));
  } else {
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, (float(texel.y) + 0.5) / float(n), r,
                                           mu_s);
    vec3 j = gather_order(atmosphere, r, mu_s, source_kind, false, moment_up, moment_sun);
    imageStore(u_order, texel + ivec2(kFieldMean * n, 0), vec4(j, 1.0));
    imageStore(u_order, texel + ivec2(kFieldMomentUp * n, 0), vec4(moment_up, 1.0));
    imageStore(u_order, texel + ivec2(kFieldMomentSun * n, 0), vec4(moment_sun, 1.0));
  }
}
