// Atmospheres derived from a day's inputs (atmosphere_inputs.h): the
// formulas against published tables and hand-worked values, the shipped
// preset of the measured day, and one failing case per validation rule.
#include "atmosphere/atmosphere_inputs.h"
#include "atmosphere/math/shared_math.h"
#include "atmosphere/reference/medium.h"
#include "core/data_paths.h"
#include "core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <functional>

#include "tests/atmosphere/atmosphere_json.h"
#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

nlohmann::json kider_atmosphere() { return shipped_atmosphere("earth_kider_2013"); }

AtmosphereModel parse(const nlohmann::json& a) { return parse_atmosphere_json(a, "day.json"); }

std::string error_after(const std::function<void(nlohmann::json&)>& edit) {
  return atmosphere_error_after("earth_kider_2013", "day.json", edit);
}

TEST(AtmosphereInputsTest, RayleighMatchesPenndorfsTable) {
  // Penndorf 1957, Table III (0 C), times T0 / T = 273.16 / 288.16 for 15 C,
  // as Bruneton's 2016 evaluation applies it.
  struct Row {
    double nm, at_0c;
  };
  for (Row r : {Row{360, 70.45e-6}, Row{450, 27.89e-6}, Row{550, 12.26e-6}, Row{700, 4.605e-6}}) {
    double table = r.at_0c * 273.16 / 288.16;
    EXPECT_NEAR(rayleigh_scattering_air(r.nm, 1.0, 0.035), table, 1e-3 * table) << r.nm << " nm";
  }
  // Twice the molecules, twice the scattering.
  EXPECT_DOUBLE_EQ(rayleigh_scattering_air(550, 2.0, 0.035),
                   2.0 * rayleigh_scattering_air(550, 1.0, 0.035));
  // Standard air's refractivity at 550 nm: (n - 1) 1e8 = 27782.8 (Peck and Reeder).
  EXPECT_NEAR(standard_air_refractivity(550.0), 2.77828e-4, 1e-8);
}

TEST(AtmosphereInputsTest, TheMeasuredDayHasBrunetonsAerosolsAndOzone) {
  AtmosphereModel m = parse(kider_atmosphere());
  EXPECT_EQ(m.bottom_radius, 6360e3);
  EXPECT_EQ(m.top_radius, 6420e3);
  EXPECT_EQ(m.mie_g, 0.7);
  EXPECT_EQ(m.mie_phase, MiePhase::kCornetteShanks);
  ASSERT_TRUE(m.spectrum);
  const AtmosphereSpectrum& s = *m.spectrum;
  ASSERT_EQ(s.wavelengths_nm.size(), 48u);
  EXPECT_EQ(s.wavelengths_nm.front(), 360.0);
  EXPECT_EQ(s.wavelengths_nm.back(), 830.0);
  // 500 nm is sample 14: Angstrom 0.04 (0.5 um)^-0.8 = 0.069644 over 1200 m,
  // 80 % of it scattered.
  double extinction = 0.04 * std::pow(0.5, -0.8) / 1200.0;
  EXPECT_NEAR(extinction, 5.8037e-5, 1e-9);
  EXPECT_NEAR(s.mie_scattering[14], 0.8 * extinction, 1e-12);
  EXPECT_NEAR(s.mie_absorption[14], 0.2 * extinction, 1e-12);
  // 300 DU over a tent 30 km wide: 300 * 2.687e20 / 15000 = 5.374e18 /m^3
  // at its peak, times the cross-section at 600 nm (sample 24, 5.019e-25 m^2).
  EXPECT_NEAR(s.absorber_absorption[24], 5.374e18 * 5.019e-25, 1e-12);
  // The RGB channels are the same formulas at 680, 550 and 440 nm.
  EXPECT_NEAR(m.rayleigh.scattering.g, rayleigh_scattering_air(550, 1.0, 0.035), 1e-15);
  EXPECT_NEAR(m.mie.extinction().b, 0.04 * std::pow(0.44, -0.8) / 1200.0, 1e-15);
  EXPECT_NEAR(m.solar_irradiance.g, 1.8504, 1e-12);  // ASTM G-173's 550 nm bin
  // Grass: 0.089 at 550 nm, 0.055 at 520 nm; 0.035 at 680.
  EXPECT_NEAR(m.ground_albedo.g, 0.089, 1e-12);
  EXPECT_NEAR(s.ground_albedo[16], 0.055, 1e-12);
  EXPECT_NEAR(m.ground_albedo.r, 0.035, 1e-12);
  // The path tracer takes each wavelength's albedo.
  Medium medium = make_medium(m, ReferenceMode::kSpectral);
  EXPECT_NEAR(medium.channels[19].ground_albedo, 0.089, 1e-12);
  EXPECT_NEAR(make_medium(m, ReferenceMode::kRgb).channels[0].ground_albedo, 0.035, 1e-12);
}

TEST(AtmosphereInputsTest, SurfacePressureAndTemperatureScaleRayleighOnly) {
  nlohmann::json a = kider_atmosphere();
  AtmosphereModel base = parse(a);
  a["inputs"]["surface_pressure_hpa"] = 1013.25 / 2.0;
  a["inputs"]["surface_temperature_k"] = 288.15 * 1.25;
  AtmosphereModel thin = parse(a);
  EXPECT_NEAR(thin.rayleigh.scattering.g, base.rayleigh.scattering.g * 0.5 / 1.25, 1e-18);
  EXPECT_EQ(thin.mie.scattering, base.mie.scattering);
}

TEST(AtmosphereInputsTest, HenyeyGreensteinIsTheAerosolsPhaseWhereTheInputsSaySo) {
  nlohmann::json a = kider_atmosphere();
  a["inputs"]["aerosol"]["phase_function"] = "henyey_greenstein";
  AtmosphereModel m = parse(a);
  EXPECT_EQ(m.mie_phase, MiePhase::kHenyeyGreenstein);
  shared::Atmosphere s = shared::to_shared(m);
  for (double nu : {-1.0, -0.3, 0.2, 0.9, 1.0}) {
    EXPECT_DOUBLE_EQ(shared::mie_phase(s, nu), shared::henyey_greenstein_phase(0.7, nu));
    EXPECT_DOUBLE_EQ(make_medium(m, ReferenceMode::kRgb).mie_phase_value(nu),
                     shared::henyey_greenstein_phase(0.7, nu));
  }
  // Its Legendre coefficients are g^l.
  EXPECT_NEAR(shared::mie_legendre(s, 3), 0.343, 1e-12);
  shared::Atmosphere cs = shared::to_shared(parse(kider_atmosphere()));
  EXPECT_DOUBLE_EQ(shared::mie_phase(cs, 0.4), shared::cornette_shanks_phase(0.7, 0.4));
  EXPECT_DOUBLE_EQ(shared::mie_legendre(cs, 3), shared::cornette_shanks_legendre(0.7, 3));
}

TEST(AtmosphereInputsTest, EveryInputIsChecked) {
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["aerosol"]["phase_function"] = "mie"; }),
            "day.json: atmosphere.inputs.aerosol.phase_function: 'mie' is not a phase function "
            "(cornette_shanks, henyey_greenstein)");
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["aerosol"]["single_scattering_albedo"] = 1.5; }),
            "day.json: atmosphere.inputs.aerosol.single_scattering_albedo: 1.5 is out of range "
            "[0, 1]");
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["ozone"]["dobson_units"] = -3; }),
            "day.json: atmosphere.inputs.ozone.dobson_units: -3 is out of range [0, 2000]");
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["surface_pressure_hpa"] = 0; }),
            "day.json: atmosphere.inputs.surface_pressure_hpa: 0 is out of range [0.01, 100000]");
  EXPECT_EQ(error_after([](auto& a) { a["mie_g"] = 0.5; }),
            "day.json: atmosphere.mie_g: give the coefficients or the inputs they derive from, "
            "not both");
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["ground_albedo"]["values"][3] = 2.0; }),
            "day.json: atmosphere.inputs.ground_albedo.values[3]: 2 is out of range [0, 1]");
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["ground_albedo"]["wavelengths_nm"][1] = 300; }),
            "day.json: atmosphere.inputs.ground_albedo.wavelengths_nm: must be strictly "
            "increasing");
  EXPECT_EQ(error_after([](auto& a) { a["inputs"]["aerosol"]["angstrum_alpha"] = 1; }),
            "day.json: atmosphere.inputs.aerosol.angstrum_alpha: unknown key");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
