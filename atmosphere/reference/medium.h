#pragma once
// The atmosphere as the path tracer sees it: the model's geometry and
// density profiles, and its coefficients at a list of channels. A channel is
// one wavelength: the three RGB wavelengths of the real-time techniques, or
// the model's spectral samples. Every path carries a single channel, so
// that collisions are drawn by one scalar optical depth per channel and
// the spectral and RGB modes share every line of the tracer.
#include "atmosphere/model.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace planet {

enum class ReferenceMode { kRgb, kSpectral };

const char* to_string(ReferenceMode mode);
// Throws InputError for anything but "rgb" or "spectral".
ReferenceMode parse_reference_mode(const std::string& text);

struct MediumChannel {
  double wavelength_nm = 0;
  double rayleigh_scattering = 0;  // 1/m at density 1
  double mie_scattering = 0;
  double mie_absorption = 0;
  double absorber_absorption = 0;
  double solar_irradiance = 0;  // W m^-2 nm^-1 at the top of the atmosphere
  double ground_albedo = 0;     // the Lambertian ground's, at this wavelength
  // This channel's share of linear sRGB: radiance L in this channel adds
  // L * rgb_weight to the pixel (see atmosphere/spectrum.h).
  glm::dvec3 rgb_weight{0.0};
};

struct Medium {
  double bottom_radius = 0, top_radius = 0;
  double mie_g = 0;
  MiePhase mie_phase = MiePhase::kCornetteShanks;
  // The aerosols' phase function at cosine nu.
  double mie_phase_value(double nu) const;
  double sun_angular_radius = 0;
  DensityProfile rayleigh_density{}, mie_density{}, absorber_density{};
  std::vector<MediumChannel> channels;

  struct Coefficients {
    double scattering_rayleigh, scattering_mie, absorption;
    double scattering() const { return scattering_rayleigh + scattering_mie; }
    double extinction() const { return scattering_rayleigh + scattering_mie + absorption; }
  };
  Coefficients at(const MediumChannel& c, double altitude) const {
    double d_r = density_at(rayleigh_density, altitude);
    double d_m = density_at(mie_density, altitude);
    double d_a = density_at(absorber_density, altitude);
    return {c.rayleigh_scattering * d_r, c.mie_scattering * d_m,
            c.mie_absorption * d_m + c.absorber_absorption * d_a};
  }
};

// The medium in RGB mode (the model's three wavelengths, each channel
// weighted into its own sRGB component) or in spectral mode (the model's
// spectrum, which it must have; InputError otherwise).
Medium make_medium(const AtmosphereModel& model, ReferenceMode mode);

}  // namespace planet
