#pragma once
// An atmosphere from the inputs a user has for a day and a place, rather
// than from coefficients: surface pressure and temperature, the aerosols'
// Angstrom turbidity, single-scattering albedo, asymmetry and scale height,
// the ozone column in Dobson units, and the ground's albedo. They derive the
// model's coefficients at its three RGB wavelengths and at 48 spectral
// samples, 360 to 830 nm every 10 nm, through the formulas below.
#include "atmosphere/model.h"
#include "core/json_reader.h"

#include <vector>

namespace planet {

// The spectral samples a derived atmosphere has: 360, 370, ... 830 nm.
std::vector<double> derived_wavelengths_nm();

// The extraterrestrial solar spectral irradiance (W m^-2 nm^-1), ASTM
// G-173's ETR column averaged over each 10 nm bin, at 360-830 nm, linearly
// interpolated between bins (constant beyond them).
double solar_irradiance_astm_g173(double lambda_nm);

// The ozone absorption cross-section (m^2) at 233 K, Serdyuchenko et al.
// 2014, averaged over each 10 nm bin, 360-830 nm, linearly interpolated.
double ozone_cross_section(double lambda_nm);

// The refractivity n - 1 of standard air (15 C, 101325 Pa, 0.03 % CO2),
// Peck and Reeder 1972, lambda in vacuum from 230 to 1690 nm.
double standard_air_refractivity(double lambda_nm);

// The Rayleigh scattering coefficient of air (1/m), Penndorf 1957:
//   beta = 24 pi^3 / (N lambda^4) ((n^2 - 1) / (n^2 + 2))^2 (6 + 3 rho) / (6 - 7 rho)
// at standard air's number density N_s (15 C, 101325 Pa), times
// `density_ratio` = N / N_s (the Lorentz-Lorenz term grows as N^2, so beta
// as N). rho is the depolarisation factor; Penndorf's 0.035 reproduces his
// table (Bruneton's 2016 evaluation uses it) to 0.3 %.
double rayleigh_scattering_air(double lambda_nm, double density_ratio, double depolarization);

// One Dobson unit: molecules per m^2 in a column.
constexpr double kDobsonUnit = 2.687e20;

// Parses the "inputs" object of an atmosphere and fills `model`'s
// components, solar irradiance, Mie asymmetry and phase, ground albedo and
// spectrum from them; `model` comes with its radii and RGB wavelengths.
// InputError naming the file and key for any value out of its range.
void derive_atmosphere(JsonObject inputs, AtmosphereModel& model);

}  // namespace planet
