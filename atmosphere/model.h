#pragma once
// A body's atmosphere: a spherical shell between bottom_radius and
// top_radius, made of components (Rayleigh, Mie, an absorber) that each have
// scattering and absorption coefficients at sample wavelengths and a
// density profile of layers. Every technique and the ground truth read this
// one description. Values come from the body's file, never from code.
#include "sim/json_reader.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace planet {

// Bruneton 2017's layer: density(h) = clamp(exp_term * exp(exp_scale * h)
// + linear_term * h + constant_term, 0, 1) for h below `width` (the last
// layer extends to the top). Exponential, linear and tent profiles are all
// one or two such layers.
struct DensityLayer {
  double width = 0;  // metres
  double exp_term = 0;
  double exp_scale = 0;    // 1/m
  double linear_term = 0;  // 1/m
  double constant_term = 0;
};

struct DensityProfile {
  std::array<DensityLayer, 2> layers{};
  double density(double altitude) const;
};

enum class PhaseKind { kRayleigh, kMie, kNone };

struct AtmosphereComponent {
  std::string name;
  PhaseKind phase = PhaseKind::kNone;
  glm::dvec3 scattering{0.0};  // 1/m at the RGB wavelengths
  glm::dvec3 absorption{0.0};  // 1/m
  DensityProfile density;
  glm::dvec3 extinction() const { return scattering + absorption; }
};

struct AtmosphereModel {
  double bottom_radius = 0;  // metres
  double top_radius = 0;
  // The three wavelengths (nm) the RGB coefficients belong to: red, green, blue.
  glm::dvec3 wavelengths_nm{680.0, 550.0, 440.0};
  glm::dvec3 solar_irradiance{1.0};  // at the top of the atmosphere
  double sun_angular_radius = 0;     // radians
  double mie_g = 0;                  // Henyey-Greenstein / Cornette-Shanks asymmetry
  double ground_albedo = 0;
  AtmosphereComponent rayleigh, mie, absorber;
};

// Parses and validates the "atmosphere" object of a body file.
AtmosphereModel parse_atmosphere(JsonObject atmosphere);

}  // namespace planet
