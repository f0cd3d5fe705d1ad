#include "atmosphere/reference/medium.h"

#include "atmosphere/math/shared_math.h"
#include "atmosphere/spectrum.h"
#include "core/error.h"

#include <fmt/format.h>

namespace planet {

const char* to_string(ReferenceMode mode) {
  return mode == ReferenceMode::kRgb ? "rgb" : "spectral";
}

ReferenceMode parse_reference_mode(const std::string& text) {
  if (text == "rgb") return ReferenceMode::kRgb;
  if (text == "spectral") return ReferenceMode::kSpectral;
  throw InputError(fmt::format("'{}' is not a reference mode (rgb, spectral)", text));
}

double Medium::mie_phase_value(double nu) const {
  return mie_phase == MiePhase::kHenyeyGreenstein ? shared::henyey_greenstein_phase(mie_g, nu)
                                                  : shared::cornette_shanks_phase(mie_g, nu);
}

Medium make_medium(const AtmosphereModel& model, ReferenceMode mode) {
  Medium m;
  m.bottom_radius = model.bottom_radius;
  m.top_radius = model.top_radius;
  m.mie_g = model.mie_g;
  m.mie_phase = model.mie_phase;
  m.sun_angular_radius = model.sun_angular_radius;
  m.rayleigh_density = model.rayleigh.density;
  m.mie_density = model.mie.density;
  m.absorber_density = model.absorber.density;
  if (mode == ReferenceMode::kRgb) {
    for (int i = 0; i < 3; ++i) {
      MediumChannel c;
      c.wavelength_nm = model.wavelengths_nm[i];
      c.rayleigh_scattering = model.rayleigh.scattering[i];
      c.mie_scattering = model.mie.scattering[i];
      c.mie_absorption = model.mie.absorption[i];
      c.absorber_absorption = model.absorber.extinction()[i];
      c.solar_irradiance = model.solar_irradiance[i];
      c.ground_albedo = model.ground_albedo[i];
      c.rgb_weight[i] = 1.0;
      m.channels.push_back(c);
    }
    return m;
  }
  if (!model.spectrum) {
    throw InputError("the atmosphere has no \"spectrum\": it can only be rendered in rgb mode");
  }
  const AtmosphereSpectrum& s = *model.spectrum;
  std::vector<glm::dvec3> weights = srgb_weights(s.wavelengths_nm);
  for (size_t i = 0; i < s.wavelengths_nm.size(); ++i) {
    MediumChannel c;
    c.wavelength_nm = s.wavelengths_nm[i];
    c.rayleigh_scattering = s.rayleigh_scattering[i];
    c.mie_scattering = s.mie_scattering[i];
    c.mie_absorption = s.mie_absorption[i];
    c.absorber_absorption = s.absorber_absorption[i];
    c.solar_irradiance = s.solar_irradiance[i];
    c.ground_albedo = s.ground_albedo.empty() ? model.ground_albedo.g : s.ground_albedo[i];
    c.rgb_weight = weights[i];
    m.channels.push_back(c);
  }
  return m;
}

}  // namespace planet
