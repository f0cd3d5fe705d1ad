// An atmosphere whose every number is its own, for the tests that each form
// of the atmosphere (atmosphere/model.h) holds what the model says: a
// converter that puts one field in another's place, or drops one, shows as
// a wrong value. The structured bindings name every field of the model's
// types: a field added to one of them stops this file compiling until it is
// given a value here and checked in each form (atmosphere_forms_test.cpp,
// atmosphere_block_gl_test.cpp).
#pragma once
#include "atmosphere/model.h"

#include <ostream>

namespace glm {

// GoogleTest prints a vector that differs by this (found by argument-
// dependent lookup), not as its bytes.
template <length_t L, typename T, qualifier Q>
void PrintTo(const vec<L, T, Q>& v, std::ostream* os) {
  *os << "(";
  for (length_t i = 0; i < L; ++i) *os << (i ? ", " : "") << v[i];
  *os << ")";
}

}  // namespace glm

namespace planet::forms {

// 1001.0625, 1002.125, ...: every number its own, so that one in another's
// place cannot pass for it.
class DistinctValues {
 public:
  double next() { return 1000.0 + double(++count_) * 1.0625; }
  glm::dvec3 next3() {
    double x = next(), y = next();
    return {x, y, next()};
  }

 private:
  int count_ = 0;
};

inline DensityProfile distinct_profile(DistinctValues& v) {
  DensityProfile p{};
  for (DensityLayer& layer : p.layers) {
    auto& [width, exp_term, exp_scale, linear_term, constant_term] = layer;
    width = v.next();
    exp_term = v.next();
    exp_scale = -1.0 / v.next();
    linear_term = 1.0 / v.next();
    constant_term = v.next();
  }
  return p;
}

inline AtmosphereComponent distinct_component(DistinctValues& v, const char* component_name,
                                              PhaseKind phase_kind) {
  AtmosphereComponent c;
  auto& [name, phase, scattering, absorption, density] = c;
  name = component_name;
  phase = phase_kind;
  scattering = v.next3() * 1e-9;
  absorption = v.next3() * 1e-9;
  density = distinct_profile(v);
  return c;
}

// `samples` spectral samples from 400 nm, 20 nm apart.
inline AtmosphereModel distinct_model(MiePhase phase_function, size_t samples = 4) {
  DistinctValues v;
  AtmosphereModel m;
  auto& [bottom_radius, top_radius, wavelengths_nm, solar_irradiance, sun_angular_radius, mie_g,
         mie_phase, ground_albedo, rayleigh, mie, absorber, spectrum] = m;
  bottom_radius = v.next() * 1e3;
  top_radius = v.next() * 2e3;
  wavelengths_nm = glm::dvec3(680.5, 550.5, 440.5);
  solar_irradiance = v.next3();
  sun_angular_radius = v.next() * 1e-6;
  mie_g = v.next() * 1e-4;
  mie_phase = phase_function;
  ground_albedo = v.next3() * 1e-4;
  rayleigh = distinct_component(v, "rayleigh", PhaseKind::kRayleigh);
  mie = distinct_component(v, "mie", PhaseKind::kMie);
  absorber = distinct_component(v, "absorber", PhaseKind::kNone);
  AtmosphereSpectrum s;
  auto& [s_wavelengths_nm, s_solar_irradiance, s_rayleigh_scattering, s_mie_scattering,
         s_mie_absorption, s_absorber_absorption, s_ground_albedo] = s;
  for (size_t i = 0; i < samples; ++i) {
    s_wavelengths_nm.push_back(400.0 + 20.0 * double(i));
    s_solar_irradiance.push_back(v.next());
    s_rayleigh_scattering.push_back(v.next() * 1e-9);
    s_mie_scattering.push_back(v.next() * 1e-9);
    s_mie_absorption.push_back(v.next() * 1e-9);
    s_absorber_absorption.push_back(v.next() * 1e-9);
    s_ground_albedo.push_back(v.next() * 1e-4);
  }
  spectrum = s;
  return m;
}

}  // namespace planet::forms
