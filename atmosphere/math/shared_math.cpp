// The shared math's one C++ translation unit: the GLSL files compiled in
// double (see shared_math.h).
#include "atmosphere/math/shared_math.h"

namespace planet::shared {

using namespace glm;
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
// In the order the shaders include them (atmosphere_block.glsl).
// clang-format off
#include "atmosphere/shaders/geometry.glsl"
#include "atmosphere/shaders/density.glsl"
#include "atmosphere/shaders/phase.glsl"
#include "atmosphere/shaders/lut_coordinates.glsl"
#include "atmosphere/shaders/transmittance.glsl"
#include "atmosphere/shaders/sun.glsl"
#include "atmosphere/shaders/occluded_sun.glsl"
// clang-format on
#undef IN
#undef OUT
#undef INOUT

Atmosphere to_shared(const AtmosphereModel& m) {
  Atmosphere a{};
  a.bottom_radius = m.bottom_radius;
  a.top_radius = m.top_radius;
  a.solar_irradiance = m.solar_irradiance;
  a.sun_angular_radius = m.sun_angular_radius;
  a.rayleigh_scattering = m.rayleigh.scattering;
  a.rayleigh_density = m.rayleigh.density;
  a.mie_scattering = m.mie.scattering;
  a.mie_extinction = m.mie.extinction();
  a.mie_g = m.mie_g;
  a.mie_density = m.mie.density;
  a.absorption_extinction = m.absorber.extinction();
  a.absorption_density = m.absorber.density;
  a.ground_albedo = Real3(m.ground_albedo);
  a.mie_phase_hg = m.mie_phase == MiePhase::kHenyeyGreenstein ? 1.0 : 0.0;
  return a;
}

}  // namespace planet::shared
