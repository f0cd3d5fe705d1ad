#pragma once
// A body's atmosphere: a spherical shell between bottom_radius and
// top_radius, made of components (Rayleigh, Mie, an absorber) that each have
// scattering and absorption coefficients at sample wavelengths and a
// density profile of layers. Every technique and the ground truth read this
// one description. Values come from the body's file, never from code.
#include "atmosphere/math/definitions.h"
#include "core/json_reader.h"
#include "sim/body.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace planet {

// A density profile (Bruneton 2017's two layers) is the shared math's own
// type (atmosphere/shaders/definitions.glsl), so that the model, the ground
// truth and the shaders read one description.
using DensityLayer = shared::DensityLayer;
using DensityProfile = shared::DensityProfile;

// The density at an altitude, as profile_density (density.glsl) has it, but
// for the ground truth's path tracer, which calls it millions of times a
// second: the exponential only where the layer has one, and the altitude
// as it is (the tracer never samples below the bottom).
double density_at(const DensityProfile& profile, double altitude);

enum class PhaseKind { kRayleigh, kMie, kNone };

// The aerosols' phase function: Cornette and Shanks 1992 (Bruneton 2017's
// and Hillaire 2020's), or Henyey and Greenstein 1941.
enum class MiePhase { kCornetteShanks = 0, kHenyeyGreenstein = 1 };
const char* to_string(MiePhase phase);

struct AtmosphereComponent {
  std::string name;
  PhaseKind phase = PhaseKind::kNone;
  glm::dvec3 scattering{0.0};  // 1/m at the RGB wavelengths
  glm::dvec3 absorption{0.0};  // 1/m
  DensityProfile density{};
  glm::dvec3 extinction() const { return scattering + absorption; }
};

// The atmosphere at the spectral samples the ground truth renders with:
// every vector holds one value per wavelength. Coefficients are at density 1
// (multiply by the component's density profile), like the RGB ones.
struct AtmosphereSpectrum {
  std::vector<double> wavelengths_nm;       // increasing, within 360-830 nm
  std::vector<double> solar_irradiance;     // W m^-2 nm^-1 at the top of the atmosphere
  std::vector<double> rayleigh_scattering;  // 1/m
  std::vector<double> mie_scattering;       // 1/m
  std::vector<double> mie_absorption;       // 1/m
  std::vector<double> absorber_absorption;  // 1/m
  // The ground's albedo per sample; empty: the RGB albedo's (grey) value.
  std::vector<double> ground_albedo;
};

struct AtmosphereModel {
  double bottom_radius = 0;  // metres
  double top_radius = 0;
  // The three wavelengths (nm) the RGB coefficients belong to: red, green, blue.
  glm::dvec3 wavelengths_nm{680.0, 550.0, 440.0};
  glm::dvec3 solar_irradiance{1.0};  // at the top of the atmosphere
  double sun_angular_radius = 0;     // radians
  double mie_g = 0;                  // Henyey-Greenstein / Cornette-Shanks asymmetry
  MiePhase mie_phase = MiePhase::kCornetteShanks;
  glm::dvec3 ground_albedo{0.0};  // at the RGB wavelengths
  AtmosphereComponent rayleigh, mie, absorber;
  // Spectral samples for the ground truth; absent, only RGB renders.
  std::optional<AtmosphereSpectrum> spectrum;
};

// The fewest spectral samples a body file may give, and the range they must
// span: the CIE 1931 observer sees nearly nothing outside 380-780 nm.
constexpr size_t kMinSpectralSamples = 16;
constexpr double kSpectrumMinNm = 380.0, kSpectrumMaxNm = 780.0;

// Parses and validates the "atmosphere" object of a body file: the
// coefficients given directly, or derived from a day's "inputs"
// (atmosphere_inputs.h).
AtmosphereModel parse_atmosphere(JsonObject atmosphere);
// The body's atmosphere, parsed from its file; InputError naming the file
// for an airless body.
AtmosphereModel load_atmosphere(const Body& body);

// The model with its scattering coefficients (Rayleigh and Mie, RGB and
// spectral) multiplied by `factor`: the dense variants of the scenes.
AtmosphereModel with_scattering_scaled(AtmosphereModel model, double factor);
// The same for the absorption coefficients (Mie's and the absorber's).
AtmosphereModel with_absorption_scaled(AtmosphereModel model, double factor);

// The model on a body of another bottom radius. At the preset's thickness
// ratio (absolute_thickness false) every length is scaled with the radius,
// the shell's thickness and the profiles' heights, and the coefficients
// divided by the same factor, so that every optical depth along a vertical
// stays as it was: only the curvature changes. At its absolute thickness
// the shell and its profiles keep their heights in metres.
AtmosphereModel with_bottom_radius(AtmosphereModel model, double bottom_radius,
                                   bool absolute_thickness);

// Rayleigh's and Mie's exponential scale heights multiplied by `factor`,
// their coefficients set so that each one's optical depth from the bottom
// to the top along a vertical stays as it was.
AtmosphereModel with_scale_heights_scaled(AtmosphereModel model, double factor);

// The model whose three RGB channels are its spectrum's samples i, j and k
// (solar irradiance, every coefficient, the ground's albedo): how a
// technique that draws three wavelengths draws the whole spectrum, three
// at a time. InputError for a model without a spectrum.
AtmosphereModel with_rgb_at_spectral_samples(AtmosphereModel model, size_t i, size_t j, size_t k);

}  // namespace planet
