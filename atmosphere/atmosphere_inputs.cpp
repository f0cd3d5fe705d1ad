#include "atmosphere/atmosphere_inputs.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace planet {

namespace {

constexpr double kFirstNm = 360.0, kStepNm = 10.0;
constexpr size_t kSamples = 48;  // 360 to 830 nm

// ASTM G-173 extraterrestrial irradiance, W m^-2 nm^-1, averaged over
// [lambda, lambda + 10 nm) (the binning of Bruneton 2017's demo).
constexpr std::array<double, kSamples> kSolarIrradiance = {
    1.11776, 1.14259, 1.01249, 1.14716, 1.72765, 1.73054, 1.6887,  1.61253, 1.91198, 2.03474,
    2.02042, 2.02212, 1.93377, 1.95809, 1.91686, 1.8298,  1.8685,  1.8931,  1.85149, 1.8504,
    1.8341,  1.8345,  1.8147,  1.78158, 1.7533,  1.6965,  1.68194, 1.64654, 1.6048,  1.52143,
    1.55622, 1.5113,  1.474,   1.4482,  1.41018, 1.36775, 1.34188, 1.31429, 1.28303, 1.26758,
    1.2367,  1.2082,  1.18737, 1.14683, 1.12362, 1.1058,  1.07124, 1.04992};

// Ozone cross-sections at 233 K (Serdyuchenko et al. 2014), m^2, averaged
// over the same bins.
constexpr std::array<double, kSamples> kOzoneCrossSection = {
    1.18e-27,  2.182e-28, 2.818e-28, 6.636e-28, 1.527e-27, 2.763e-27, 5.52e-27,  8.451e-27,
    1.582e-26, 2.316e-26, 3.669e-26, 4.924e-26, 7.752e-26, 9.016e-26, 1.48e-25,  1.602e-25,
    2.139e-25, 2.755e-25, 3.091e-25, 3.5e-25,   4.266e-25, 4.672e-25, 4.398e-25, 4.701e-25,
    5.019e-25, 4.305e-25, 3.74e-25,  3.215e-25, 2.662e-25, 2.238e-25, 1.852e-25, 1.473e-25,
    1.209e-25, 9.423e-26, 7.455e-26, 6.566e-26, 5.105e-26, 4.15e-26,  4.228e-26, 3.237e-26,
    2.451e-26, 2.801e-26, 2.534e-26, 1.624e-26, 1.465e-26, 2.078e-26, 1.383e-26, 7.105e-27};

// A 10 nm table at lambda: linear between samples, held beyond the ends.
double table_at(const std::array<double, kSamples>& table, double lambda_nm) {
  double x = (lambda_nm - kFirstNm) / kStepNm;
  if (x <= 0.0) return table.front();
  if (x >= double(kSamples - 1)) return table.back();
  size_t i = size_t(x);
  double f = x - double(i);
  return table[i] * (1.0 - f) + table[i + 1] * f;
}

// Standard air: 15 C and 101325 Pa (Peck and Reeder's and Penndorf's).
constexpr double kStandardTemperature = 288.15, kStandardPressure = 101325.0;
constexpr double kBoltzmann = 1.380649e-23;

// A curve given as samples, {"wavelengths_nm": [...], "values": [...]}:
// linear between them, held beyond the ends.
struct SampledCurve {
  std::vector<double> wavelengths_nm, values;
  double at(double lambda_nm) const {
    if (lambda_nm <= wavelengths_nm.front()) return values.front();
    if (lambda_nm >= wavelengths_nm.back()) return values.back();
    size_t i = size_t(std::upper_bound(wavelengths_nm.begin(), wavelengths_nm.end(), lambda_nm) -
                      wavelengths_nm.begin());
    double f = (lambda_nm - wavelengths_nm[i - 1]) / (wavelengths_nm[i] - wavelengths_nm[i - 1]);
    return values[i - 1] * (1.0 - f) + values[i] * f;
  }
};

SampledCurve parse_albedo(JsonObject& inputs) {
  if (inputs.raw("ground_albedo").is_number()) {
    double a = inputs.number("ground_albedo", 0.0, 1.0);
    return {{550.0}, {a}};
  }
  JsonObject o = inputs.object("ground_albedo");
  o.string_or("source", "");
  SampledCurve c;
  c.wavelengths_nm = o.number_list("wavelengths_nm", 200.0, 3000.0);
  for (size_t i = 1; i < c.wavelengths_nm.size(); ++i) {
    if (c.wavelengths_nm[i] <= c.wavelengths_nm[i - 1]) {
      o.fail("wavelengths_nm", "must be strictly increasing");
    }
  }
  c.values = o.numbers("values", c.wavelengths_nm.size(), 0.0, 1.0);
  o.finish();
  return c;
}

DensityProfile exponential(double scale_height) {
  DensityProfile p{};
  p.layers[1] = {0.0, 1.0, -1.0 / scale_height, 0.0, 0.0};
  return p;
}

}  // namespace

std::vector<double> derived_wavelengths_nm() {
  std::vector<double> w;
  for (size_t i = 0; i < kSamples; ++i) w.push_back(kFirstNm + kStepNm * double(i));
  return w;
}

double solar_irradiance_astm_g173(double lambda_nm) { return table_at(kSolarIrradiance, lambda_nm); }

double ozone_cross_section(double lambda_nm) { return table_at(kOzoneCrossSection, lambda_nm); }

double standard_air_refractivity(double lambda_nm) {
  // sigma: the wavenumber in 1/um.
  double sigma2 = 1.0 / (lambda_nm * 1e-3 * lambda_nm * 1e-3);
  return (5791817.0 / (238.0185 - sigma2) + 167909.0 / (57.362 - sigma2)) * 1e-8;
}

double rayleigh_scattering_air(double lambda_nm, double density_ratio, double depolarization) {
  const double pi = glm::pi<double>();
  double n = 1.0 + standard_air_refractivity(lambda_nm);
  double lorentz_lorenz = (n * n - 1.0) / (n * n + 2.0);
  double number_density = kStandardPressure / (kBoltzmann * kStandardTemperature);
  double lambda = lambda_nm * 1e-9;
  double king = (6.0 + 3.0 * depolarization) / (6.0 - 7.0 * depolarization);
  return 24.0 * pi * pi * pi / (number_density * std::pow(lambda, 4.0)) * lorentz_lorenz *
         lorentz_lorenz * king * density_ratio;
}

void derive_atmosphere(JsonObject in, AtmosphereModel& m) {
  in.string_or("source", "");
  double thickness = m.top_radius - m.bottom_radius;

  // Molecules: Rayleigh scaled by the number density at the surface.
  double pressure = in.number_or("surface_pressure_hpa", 1013.25, 0.01, 1e5) * 100.0;
  double temperature = in.number_or("surface_temperature_k", kStandardTemperature, 50.0, 1000.0);
  double density_ratio = (pressure / kStandardPressure) * (kStandardTemperature / temperature);
  double rayleigh_height = in.number_or("rayleigh_scale_height_m", 8000.0, 1.0, thickness);
  double depolarization = in.number_or("rayleigh_depolarization", 0.035, 0.0, 0.1);

  // Aerosols: the Angstrom law gives the optical depth of a vertical
  // column, beta (lambda / 1 um)^-alpha; spread over an exponential of
  // scale height H, the extinction at the surface is that over H.
  JsonObject aerosol = in.object("aerosol");
  aerosol.string_or("source", "");
  double alpha = aerosol.number("angstrom_alpha", -1.0, 4.0);
  double beta = aerosol.number("angstrom_beta", 0.0, 5.0);
  double albedo = aerosol.number("single_scattering_albedo", 0.0, 1.0);
  m.mie_g = aerosol.number("asymmetry", -0.999, 0.999);
  std::string phase = aerosol.string_or("phase_function", "cornette_shanks");
  if (phase == "cornette_shanks") {
    m.mie_phase = MiePhase::kCornetteShanks;
  } else if (phase == "henyey_greenstein") {
    m.mie_phase = MiePhase::kHenyeyGreenstein;
  } else {
    aerosol.fail("phase_function",
                 fmt::format("'{}' is not a phase function (cornette_shanks, henyey_greenstein)",
                             phase));
  }
  double aerosol_height = aerosol.number("scale_height_m", 1.0, thickness);
  aerosol.finish();

  // Ozone: the column spread over a tent; its peak number density is the
  // column over the tent's integral (half its width).
  JsonObject ozone = in.object("ozone");
  ozone.string_or("source", "");
  double dobson = ozone.number("dobson_units", 0.0, 2000.0);
  double center = ozone.number_or("center_m", 25000.0, 0.0, thickness);
  double width = ozone.number_or("width_m", 30000.0, 1.0, 2.0 * thickness);
  double half = 0.5 * width;
  if (center - half < 0.0 || center + half > thickness) {
    ozone.fail("width_m", fmt::format("the tent [{:g}, {:g}] m must lie inside the atmosphere "
                                      "[0, {:g}] m",
                                      center - half, center + half, thickness));
  }
  ozone.finish();
  double ozone_peak = dobson * kDobsonUnit / half;

  SampledCurve ground = parse_albedo(in);
  in.finish();

  auto rayleigh = [&](double l) {
    return rayleigh_scattering_air(l, density_ratio, depolarization);
  };
  auto aerosol_extinction = [&](double l) {
    return beta * std::pow(l / 1000.0, -alpha) / aerosol_height;
  };
  auto ozone_absorption = [&](double l) { return ozone_cross_section(l) * ozone_peak; };

  m.rayleigh = {"rayleigh", PhaseKind::kRayleigh, {}, glm::dvec3(0.0), exponential(rayleigh_height)};
  m.mie = {"mie", PhaseKind::kMie, {}, {}, exponential(aerosol_height)};
  m.absorber = {"absorber", PhaseKind::kNone, glm::dvec3(0.0), {}, {}};
  m.absorber.density.layers[0] = {center, 0.0, 0.0, 1.0 / half, 1.0 - center / half};
  m.absorber.density.layers[1] = {0.0, 0.0, 0.0, -1.0 / half, 1.0 + center / half};
  for (int i = 0; i < 3; ++i) {
    double l = m.wavelengths_nm[i];
    m.solar_irradiance[i] = solar_irradiance_astm_g173(l);
    m.rayleigh.scattering[i] = rayleigh(l);
    m.mie.scattering[i] = albedo * aerosol_extinction(l);
    m.mie.absorption[i] = (1.0 - albedo) * aerosol_extinction(l);
    m.absorber.absorption[i] = ozone_absorption(l);
    m.ground_albedo[i] = ground.at(l);
  }

  AtmosphereSpectrum s;
  s.wavelengths_nm = derived_wavelengths_nm();
  for (double l : s.wavelengths_nm) {
    s.solar_irradiance.push_back(solar_irradiance_astm_g173(l));
    s.rayleigh_scattering.push_back(rayleigh(l));
    s.mie_scattering.push_back(albedo * aerosol_extinction(l));
    s.mie_absorption.push_back((1.0 - albedo) * aerosol_extinction(l));
    s.absorber_absorption.push_back(ozone_absorption(l));
    s.ground_albedo.push_back(ground.at(l));
  }
  m.spectrum = std::move(s);
}

}  // namespace planet
