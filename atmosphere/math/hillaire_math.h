#pragma once
// Hillaire 2020's integrals (atmosphere/shaders/hillaire_functions.glsl) as
// C++ in double, compiled once in hillaire_math.cpp: the CPU side against
// which the tests check the GPU's LUTs. On the CPU the transmittance is
// integrated directly (kTransmittanceSteps samples, what the GPU's LUT
// stores at its texels) and the multiple-scattering LUT reads zero, so
// that the CPU evaluates the LUT passes themselves; an order of scattering
// reads the previous one from a table given to gather_order_from.
#include "atmosphere/math/shared_math.h"

namespace planet::hillaire {

using shared::Atmosphere;
using shared::Real;
using shared::Real2;
using shared::Real3;

#include "atmosphere/shaders/hillaire_definitions.glsl"

static_assert(kFieldDegree == 4, "field_basis and scattered_field are written out to degree 4");

// hillaire_functions.glsl, those the C++ side calls.
void multiple_scattering_lut_r_mu_s_from_uv(const Atmosphere& atmosphere, Real u, Real v, Real& r,
                                            Real& mu_s);
int scattering_order_width(int order);
int scattering_order_height(int order);
Real regrid_texture_coord(Real u, int from, int to);
Real field_basis(int part, Real x, Real y, Real z);
Real3 field_part(const FieldMoments& f, int part);
Real forward_gain_times_extinction(Real g, Real hg, Real nu, Real tau);
Real mie_column_to_top(const Atmosphere& atmosphere, Real r, Real mu, int steps);
void forward_gain_lut_nu_tau_from_uv(Real u, Real v, Real& nu, Real& tau);
Real3 multiple_scattering_texel(const Atmosphere& atmosphere, Real r, Real mu_s);
Real ground_gather_radius(const Atmosphere& atmosphere);
Real3 with_geometric_tail(const Real3& j_before_last, const Real3& j_last, const Real3& x_sum,
                          const Real3& x_last);

// gather_order for order `order` (from 1: the light of that order arriving
// at (r, mu_s), see there) with the order before read from
// `previous_order`: an RGBA float table as the GPU holds it
// (HillaireTechnique::scattering_order_lut: the parts side by side over h
// rows of that order's grid, the ground's irradiance in row h), sampled as
// GL samples a texture (bilinear between texel centres, clamped to the
// edge). Null for the first order, which reads no table.
FieldMoments gather_order_from(const float* previous_order, int order, const Atmosphere& atmosphere,
                               Real r, Real mu_s, bool ground_irradiance);

}  // namespace planet::hillaire
