// Hillaire 2020's integrals in their one C++ translation unit (see
// hillaire_math.h), with the lookups they call answered on the CPU.
#include "atmosphere/math/hillaire_math.h"

namespace planet::hillaire {

using namespace glm;
using namespace shared;
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&

namespace {

// The table that scattering_order_lookup and ground_order_lookup read, and
// the order it holds, for the one call of gather_order_from in progress on
// this thread.
thread_local const float* t_previous_order = nullptr;
thread_local int t_previous_order_number = 0;

Real3 sample_table(const float* table, int width, int height, Real u, Real v) {
  Real x = glm::clamp(u * width - 0.5, 0.0, double(width - 1));
  Real y = glm::clamp(v * height - 0.5, 0.0, double(height - 1));
  int x0 = int(x), y0 = int(y);
  int x1 = glm::min(x0 + 1, width - 1), y1 = glm::min(y0 + 1, height - 1);
  Real fx = x - x0, fy = y - y0;
  auto at = [&](int i, int j) {
    const float* t = table + (size_t(j) * size_t(width) + size_t(i)) * 4;
    return Real3(t[0], t[1], t[2]);
  };
  return glm::mix(glm::mix(at(x0, y0), at(x1, y0), fx), glm::mix(at(x0, y1), at(x1, y1), fx), fy);
}

}  // namespace

// The lookups the shared integrals call (hillaire_functions.glsl's list).
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_to_top(atmosphere, r, mu, kTransmittanceSteps);
}
Real3 multiple_scattering_lookup(Real, Real, int) { return Real3(0.0); }
Real3 scattering_order_lookup(Real u, Real v, int part);
Real3 ground_order_lookup(IN(Atmosphere) atmosphere, Real mu_s);
Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau);
Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu);
// The CPU's skies have no terrain.
Real terrain_sun_visibility(IN(Real3)) { return Real(1.0); }
// Nor a Moon.
Real3 eclipse_sun_share(IN(Real3), IN(Real3)) { return Real3(1.0); }

// In this order, each file using the ones before it.
// clang-format off
#include "atmosphere/shaders/sunlight.glsl"
#include "atmosphere/shaders/ground.glsl"
#include "atmosphere/shaders/hillaire_luts.glsl"
#include "atmosphere/shaders/hillaire_functions.glsl"
#include "atmosphere/shaders/hillaire_orders.glsl"
// clang-format on

Real3 scattering_order_lookup(Real u, Real v, int part) {
  if (!t_previous_order) return Real3(0.0);
  const int w = scattering_order_width(t_previous_order_number);
  const int h = scattering_order_height(t_previous_order_number);
  const Real pu = regrid_texture_coord(u, kMultipleScatteringLutWidth, w);
  const Real pv = regrid_texture_coord(v, kMultipleScatteringLutHeight, h);
  return sample_table(t_previous_order, kFieldParts * w, h + 1, (part + pu) / kFieldParts,
                      pv * h / (h + 1));
}

Real3 ground_order_lookup(IN(Atmosphere), Real mu_s) {
  if (!t_previous_order) return Real3(0.0);
  const int w = scattering_order_width(t_previous_order_number);
  const int h = scattering_order_height(t_previous_order_number);
  const Real u =
      regrid_texture_coord(ground_irradiance_lut_u_from_mu_s(mu_s), kMultipleScatteringLutWidth, w);
  return sample_table(t_previous_order, kFieldParts * w, h + 1, u / kFieldParts,
                      (h + 0.5) / (h + 1));
}

Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return mie_column_to_top(atmosphere, r, mu, kTransmittanceSteps);
}

// The forward gain summed directly, as the GPU's LUT holds it at its texels.
Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau) {
  return forward_gain_times_extinction(atmosphere.mie_g, atmosphere.mie_phase_hg, nu, tau);
}

FieldMoments gather_order_from(const float* previous_order, int order, const Atmosphere& atmosphere,
                               Real r, Real mu_s, bool ground_irradiance) {
  t_previous_order = previous_order;
  t_previous_order_number = order - 1;
  FieldMoments f = gather_order(
      atmosphere, r, mu_s, order == 1 ? kSourceFirstOrder : kSourceNextOrder, ground_irradiance);
  t_previous_order = nullptr;
  return f;
}

#undef IN
#undef OUT
#undef INOUT

}  // namespace planet::hillaire
