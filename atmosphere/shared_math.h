#pragma once
// atmosphere/shaders/atmosphere_functions.glsl compiled as C++ in double
// precision: the CPU side of the shared math (Bruneton's reference
// implementation does the same with its functions.glsl).
//
// GLSL has no `inline`, so the functions are given internal linkage here:
// each translation unit that includes this header gets its own copy of
// these small functions, instead of one definition per includer clashing
// at link time. Pass shared:: types only within one .cpp file.
#include "atmosphere/model.h"

#include <glm/glm.hpp>

namespace planet::shared {

using namespace glm;
using Real = double;
using Real2 = glm::dvec2;
using Real3 = glm::dvec3;
#define IN(T) const T&
#define OUT(T) T&
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {
#include "atmosphere/shaders/atmosphere_functions.glsl"

DensityProfile to_shared(const planet::DensityProfile& p) {
  DensityProfile out{};
  for (int i = 0; i < 2; ++i) {
    const auto& l = p.layers[size_t(i)];
    out.layers[i] = {l.width, l.exp_term, l.exp_scale, l.linear_term, l.constant_term};
  }
  return out;
}

// The model as the shared functions see it.
Atmosphere to_shared(const AtmosphereModel& m) {
  Atmosphere a{};
  a.bottom_radius = m.bottom_radius;
  a.top_radius = m.top_radius;
  a.solar_irradiance = m.solar_irradiance;
  a.sun_angular_radius = m.sun_angular_radius;
  a.rayleigh_scattering = m.rayleigh.scattering;
  a.rayleigh_density = to_shared(m.rayleigh.density);
  a.mie_scattering = m.mie.scattering;
  a.mie_extinction = m.mie.extinction();
  a.mie_g = m.mie_g;
  a.mie_density = to_shared(m.mie.density);
  a.absorption_extinction = m.absorber.extinction();
  a.absorption_density = to_shared(m.absorber.density);
  a.ground_albedo = Real3(m.ground_albedo);
  return a;
}
}  // namespace
#pragma GCC diagnostic pop
#undef IN
#undef OUT

}  // namespace planet::shared
