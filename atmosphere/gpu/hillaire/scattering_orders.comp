// One order of scattering for the multiple-scattering LUT (see "Scattering
// orders" in hillaire_orders.glsl): on the order's grid of w x h texels
// (scattering_order_width and _height), rows 0 to h-1 hold its moments
// (FieldMoments: kFieldParts parts side by side) over (mu_s, r), row h the
// ground's irradiance E_n over mu_s. The first order comes from the sun
// (compiled with FIRST_ORDER), every later one from the order before
// (u_previous_order, the same layout on that order's grid).
#include "atmosphere/gpu/hillaire/hillaire_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D u_order;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int lut_w = kMultipleScatteringLutWidth, lut_h = kMultipleScatteringLutHeight;
#ifdef FIRST_ORDER
  const int source_kind = kSourceFirstOrder;
  const int w = scattering_order_width(1), h = scattering_order_height(1);
#else
  const int source_kind = kSourceNextOrder;
  int w = scattering_order_width(u_order_number), h = scattering_order_height(u_order_number);
#endif
  if (texel.x >= w || texel.y > h) return;
  Atmosphere atmosphere = block_atmosphere();
  // The texel's centre on the LUT's grid, whose mapping it shares.
  float u = regrid_texture_coord((float(texel.x) + 0.5) / float(w), w, lut_w);
  float r, mu_s;
  if (texel.y == h) {
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, 0.5 / float(lut_h), r, mu_s);
    FieldMoments e =
        gather_order(atmosphere, ground_gather_radius(atmosphere), mu_s, source_kind, true);
    imageStore(u_order, texel, vec4(e.part[kFieldMean], 1.0));
  } else {
    float v = regrid_texture_coord((float(texel.y) + 0.5) / float(h), h, lut_h);
    multiple_scattering_lut_r_mu_s_from_uv(atmosphere, u, v, r, mu_s);
    FieldMoments f = gather_order(atmosphere, r, mu_s, source_kind, false);
    for (int part = 0; part < kFieldParts; ++part) {
      imageStore(u_order, texel + ivec2(part * w, 0), vec4(field_part(f, part), 1.0));
    }
  }
}
