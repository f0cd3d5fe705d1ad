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
// integrated directly (kTransmittanceSteps trapezoids, what the GPU's LUT
// stores at its texels); higher orders are left out, so the CPU evaluates
// the multiple-scattering pass itself, which needs none.
// Internal linkage, as in shared_math.h.
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
Real3 transmittance_lookup(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return transmittance_to_top(atmosphere, r, mu, 40);
}
Real3 multiple_scattering_lookup(IN(Atmosphere), Real, Real) { return Real3(0.0); }

#include "atmosphere/shaders/hillaire_functions.glsl"
#pragma GCC diagnostic pop
}  // namespace

#undef IN
#undef OUT
#undef INOUT

static_assert(kTransmittanceSteps == 40, "transmittance_lookup above integrates with 40 steps");

}  // namespace planet::shared
