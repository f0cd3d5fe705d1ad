#pragma once
// atmosphere/shaders/hillaire_functions.glsl compiled as C++ in double: the
// LUT mappings and the scattering integrals of Hillaire 2020, for the tests
// that check the GPU's LUTs against the same integrals on the CPU.
#include "atmosphere/shared_math.h"

namespace planet::shared {

#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&

// The lookups the shared integrals call. On the CPU the transmittance is
// integrated directly (kTransmittanceSteps samples, what the GPU's LUT
// stores at its texels); the multiple-scattering LUT reads zero, so the CPU
// evaluates the LUT passes themselves, and an order of scattering reads the
// previous one from cpu_order_table.
// Internal linkage, as in shared_math.h.
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_to_top(atmosphere, r, mu, 40);
}
Real3 multiple_scattering_lookup(Real, Real, int) { return Real3(0.0); }

// The previous order of scattering, for the CPU evaluation of the next one:
// an RGBA float table as the GPU holds it (hillaire_technique.h: the parts
// side by side over h rows, the ground's irradiance in row h), sampled as GL
// samples a texture (bilinear between texel centres, clamped to the edge).
// A test points this at the table it read back; left null, the lookups
// give zero.
const float* cpu_order_table = nullptr;

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

Real3 scattering_order_lookup(Real u, Real v, int part);
Real3 ground_order_lookup(IN(Atmosphere) atmosphere, Real mu_s);
Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau);
Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu);

#include "atmosphere/shaders/hillaire_functions.glsl"

Real3 scattering_order_lookup(Real u, Real v, int part) {
  if (!cpu_order_table) return Real3(0.0);
  const int w = kMultipleScatteringLutWidth, h = kMultipleScatteringLutHeight;
  return sample_table(cpu_order_table, kFieldParts * w, h + 1, (part + u) / kFieldParts,
                      v * h / (h + 1));
}

Real3 ground_order_lookup(IN(Atmosphere), Real mu_s) {
  if (!cpu_order_table) return Real3(0.0);
  const int w = kMultipleScatteringLutWidth, h = kMultipleScatteringLutHeight;
  return sample_table(cpu_order_table, kFieldParts * w, h + 1,
                      ground_irradiance_lut_u_from_mu_s(mu_s) / kFieldParts, (h + 0.5) / (h + 1));
}
Real mie_column_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return mie_column_to_top(atmosphere, r, mu, 40);
}

// The forward gain summed directly, as the GPU's LUT holds it at its texels.
Real forward_gain_lookup(IN(Atmosphere) atmosphere, Real nu, Real tau) {
  return forward_gain_times_extinction(atmosphere.mie_g, nu, tau);
}
#pragma GCC diagnostic pop
}  // namespace

#undef IN
#undef OUT
#undef INOUT

static_assert(kFieldDegree == 4, "field_basis and scattered_field are written out to degree 4");
static_assert(kTransmittanceSteps == 40, "transmittance_lookup above integrates with 40 steps");

}  // namespace planet::shared
