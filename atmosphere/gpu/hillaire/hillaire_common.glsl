// What every pass of the hillaire technique shares: the model's block, the
// LUT lookups the shared integrals call, and the integrals themselves
// (atmosphere/shaders/hillaire_functions.glsl, also compiled on the CPU).
#include "atmosphere/shaders/atmosphere_block.glsl"
#include "atmosphere/shaders/hillaire_definitions.glsl"

Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu);
Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu);
Real3 multiple_scattering_lookup(Real u, Real v, int part);
Real3 scattering_order_lookup(Real u, Real v, int part);
Real3 ground_order_lookup(IN(Atmosphere) atmosphere, Real mu_s);
Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau);

#include "atmosphere/gpu/terrain_shadow.glsl"

// The Moon's centre and radius in the pass's frame (atmosphere space, or
// the sky-view LUT's local frame); none while the radius is 0 (SkyFrame).
uniform vec4 u_moon;
Real3 eclipse_sun_share(IN(Real3) p, IN(Real3) sun_dir) {
  if (u_moon.w <= 0.0) return Real3(1.0);
  return occluded_sun_fraction(sun_dir, u_radii.w, u_moon.xyz - p, u_moon.w);
}
#include "atmosphere/shaders/sunlight.glsl"
#include "atmosphere/shaders/ground.glsl"
#include "atmosphere/shaders/hillaire_luts.glsl"
#include "atmosphere/shaders/hillaire_functions.glsl"
#include "atmosphere/shaders/hillaire_orders.glsl"

#ifdef TRANSMITTANCE_PASS
// The transmittance pass integrates directly and samples no LUT.
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_to_top(atmosphere, r, mu, kTransmittanceSteps);
}
Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return mie_column_to_top(atmosphere, r, mu, kTransmittanceSteps);
}
#else
// RGB: the transmittance; alpha: the Mie column (transmittance_lut.comp).
layout(binding = 2) uniform sampler2D u_transmittance_lut;

vec4 transmittance_texel(IN(Atmosphere) atmosphere, Real r, Real mu) {
  float u, v;
  transmittance_lut_uv_from_r_mu(atmosphere, r, mu, u, v);
  return texture(u_transmittance_lut, vec2(u, v));
}

Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_texel(atmosphere, r, mu).rgb;
}

Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_texel(atmosphere, r, mu).a;
}
#endif

// A part of a table whose kFieldParts parts stand side by side along u,
// at (u, v) within the part; `rows` of which the part's `height` are the
// first.
vec3 sample_part(sampler2D table, float u, float v, int part, int height, int rows) {
  vec2 uv = vec2((float(part) + u) / float(kFieldParts), v * float(height) / float(rows));
  return texture(table, uv).rgb;
}

#ifdef SCATTERING_ORDERS_PASS
// The order this pass gathers (from 2), and the one before it, which it
// scatters once more: its parts over h rows of its own grid, and the
// ground's irradiance in row h. (u, v) are on the LUT's grid.
uniform int u_order_number;
layout(binding = 7) uniform sampler2D u_previous_order;

Real3 scattering_order_lookup(Real u, Real v, int part) {
  int previous = u_order_number - 1;
  int w = scattering_order_width(previous), h = scattering_order_height(previous);
  return sample_part(u_previous_order, regrid_texture_coord(u, kMultipleScatteringLutWidth, w),
                     regrid_texture_coord(v, kMultipleScatteringLutHeight, h), part, h, h + 1);
}

Real3 ground_order_lookup(IN(Atmosphere) atmosphere, Real mu_s) {
  int previous = u_order_number - 1;
  int w = scattering_order_width(previous), h = scattering_order_height(previous);
  float u = regrid_texture_coord(ground_irradiance_lut_u_from_mu_s(mu_s),
                                 kMultipleScatteringLutWidth, w);
  return texture(u_previous_order, vec2(u / float(kFieldParts), (float(h) + 0.5) / float(h + 1)))
      .rgb;
}
#else
Real3 scattering_order_lookup(Real u, Real v, int part) { return vec3(0.0); }
Real3 ground_order_lookup(IN(Atmosphere) atmosphere, Real mu_s) { return vec3(0.0); }
#endif

#if defined(TRANSMITTANCE_PASS) || defined(MULTIPLE_SCATTERING_PASS) || \
    defined(SCATTERING_ORDERS_PASS)
// The multiple-scattering pass computes the LUT this would read.
Real3 multiple_scattering_lookup(Real u, Real v, int part) { return vec3(0.0); }
#else
layout(binding = 3) uniform sampler2D u_multiple_scattering_lut;

Real3 multiple_scattering_lookup(Real u, Real v, int part) {
  return sample_part(u_multiple_scattering_lut, u, v, part, kMultipleScatteringLutHeight,
                     kMultipleScatteringLutHeight);
}
#endif

#ifdef FORWARD_GAIN_LUT
// exp(-tau) forward_gain over (nu, tau) (forward_gain_lut.comp).
layout(binding = 8) uniform sampler2D u_forward_gain_lut;

Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau) {
  float u, v;
  forward_gain_lut_uv_from_nu_tau(nu, tau, u, v);
  return texture(u_forward_gain_lut, vec2(u, v)).r;
}
#else
// Passes that draw no view (the LUT passes), and the paper's form.
Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau) { return 0.0; }
#endif
