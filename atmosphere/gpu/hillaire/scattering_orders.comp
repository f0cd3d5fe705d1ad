// One order of scattering for the multiple-scattering LUT (see "Scattering
// orders" in hillaire_functions.glsl): rows 0 to h-1 hold the order's
// moments (FieldMoments: kFieldParts parts side by side) over
// (mu_s, r), row h the ground's irradiance E_n over mu_s. The first order
// comes from the sun (compiled with FIRST_ORDER), every later one from the
// order before (u_previous_order, the same layout).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_order;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int w = kMultipleScatteringLutWidth, h = kMultipleScatteringLutHeight;
  if (texel.x >= w || texel.y > h) return;
  Atmosphere atmosphere = block_atmosphere();
#ifdef FIRST_ORDER
  const int source_kind = kSourceFirstOrder;
#else
  const int source_kind = kSourceNextOrder;
#endif
  float u = (float(texel.x) + 0.5) / float(w);
  float r, mu_s;
  if (texel.y == h) {
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, 0.5 / float(h), r, mu_s);
    FieldMoments e =
        gather_order(atmosphere, ground_gather_radius(atmosphere), mu_s, source_kind, true);
    imageStore(u_order, texel, vec4(e.part[kFieldMean], 1.0));
  } else {
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, (float(texel.y) + 0.5) / float(h), r,
                                           mu_s);
    FieldMoments f = gather_order(atmosphere, r, mu_s, source_kind, false);
    for (int part = 0; part < kFieldParts; ++part) {
      imageStore(u_order, texel + ivec2(part * w, 0), vec4(field_part(f, part), 1.0));
    }
  }
}
