// The atmosphere model as loaded from body files: the shipped presets, and
// one failing case per validation rule with its message checked.
#include "atmosphere/model.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "sim/body.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>

#include "tests/atmosphere/atmosphere_json.h"
#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

nlohmann::json earth_atmosphere() { return shipped_atmosphere("earth"); }

AtmosphereModel parse(const nlohmann::json& a) { return parse_atmosphere_json(a, "bad.json"); }

// Parses Earth's atmosphere changed by `edit` and returns the error message.
std::string error_after(const std::function<void(nlohmann::json&)>& edit) {
  return atmosphere_error_after("earth", "bad.json", edit);
}

TEST(AtmosphereModelTest, EarthHasTheDesignValues) {
  AtmosphereModel m = parse(earth_atmosphere());
  EXPECT_EQ(m.bottom_radius, 6360e3);
  EXPECT_EQ(m.top_radius, 6460e3);
  EXPECT_EQ(m.rayleigh.scattering, glm::dvec3(5.802e-6, 13.558e-6, 33.1e-6));
  EXPECT_EQ(m.mie.scattering, glm::dvec3(3.996e-6));
  // Absorption = extinction - scattering = 4.40e-6 - 3.996e-6 = 0.404e-6 /m.
  EXPECT_NEAR(m.mie.absorption.x, 0.404e-6, 1e-18);
  EXPECT_EQ(m.absorber.absorption, glm::dvec3(0.650e-6, 1.881e-6, 0.085e-6));
  EXPECT_EQ(m.mie_g, 0.8);
  EXPECT_EQ(m.ground_albedo, glm::dvec3(0.3));
}

TEST(AtmosphereModelTest, EarthSpectrumAgreesWithItsRgbValues) {
  AtmosphereModel m = parse(earth_atmosphere());
  ASSERT_TRUE(m.spectrum);
  const AtmosphereSpectrum& s = *m.spectrum;
  EXPECT_GE(s.wavelengths_nm.size(), kMinSpectralSamples);
  EXPECT_LE(s.wavelengths_nm.front(), 380.0);
  EXPECT_GE(s.wavelengths_nm.back(), 780.0);
  for (size_t i = 0; i < s.wavelengths_nm.size(); ++i) {
    double lambda = s.wavelengths_nm[i];
    // The lambda^-4 law through 13.558e-6 at 550 nm gives the RGB values
    // at 680 and 440 nm to their 4 printed digits (Bruneton 2017's fit).
    if (lambda == 680.0) {
      EXPECT_NEAR(s.rayleigh_scattering[i] / m.rayleigh.scattering.r, 1.0, 2e-4);
      EXPECT_NEAR(s.absorber_absorption[i] / m.absorber.absorption.r, 1.0, 1e-3);
      EXPECT_NEAR(s.solar_irradiance[i], m.solar_irradiance.r, 1e-12);
    }
    if (lambda == 440.0) {
      EXPECT_NEAR(s.rayleigh_scattering[i] / m.rayleigh.scattering.b, 1.0, 2e-4);
      EXPECT_NEAR(s.absorber_absorption[i] / m.absorber.absorption.b, 1.0, 1e-3);
    }
    EXPECT_NEAR(s.mie_absorption[i], 0.404e-6, 1e-15);
  }
}

TEST(AtmosphereModelTest, EveryShippedBodyLoads) {
  for (const char* name : {"earth", "mars", "asteroid"}) {
    Body body = load_body(find_body_file(name));
    ASSERT_TRUE(body.has_atmosphere()) << name;
    AtmosphereModel m = load_atmosphere(body);
    EXPECT_TRUE(m.spectrum) << name;
    EXPECT_GT(m.top_radius, m.bottom_radius) << name;
  }
  Body mars = load_body(find_body_file("mars"));
  EXPECT_EQ(mars.shape.equatorial_radius, 3396190.0);
  EXPECT_NEAR(mars.shape.polar_radius(), 3376200.0, 1e-6);
  Body asteroid = load_body(find_body_file("asteroid"));
  EXPECT_EQ(asteroid.shape.flattening, 0.0);
}

TEST(AtmosphereModelTest, NegativeCoefficientIsRejected) {
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["rayleigh"]["scattering"][1] = -1e-6; }),
            "bad.json: atmosphere.rayleigh.scattering[1]: -1e-06 is out of range [0, 1]");
}

TEST(AtmosphereModelTest, NegativeSpectralCoefficientIsRejected) {
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["spectrum"]["absorber_absorption"][3] = -1.0; }),
            "bad.json: atmosphere.spectrum.absorber_absorption[3]: -1 is out of range [0, 1]");
}

TEST(AtmosphereModelTest, TopMustBeAboveBottom) {
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["top_radius_m"] = 6360e3; }),
            "bad.json: atmosphere.top_radius_m: 6.36e+06 must be above bottom_radius_m 6.36e+06");
}

TEST(AtmosphereModelTest, AsymmetryMustBeBelowOne) {
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["mie_g"] = 1.0; }),
            "bad.json: atmosphere.mie_g: 1 is out of range [-0.999, 0.999]");
}

TEST(AtmosphereModelTest, NumbersMustBeFinite) {
  EXPECT_EQ(error_after([](nlohmann::json& a) {
              a["ground_albedo"] = std::numeric_limits<double>::quiet_NaN();
            }),
            "bad.json: atmosphere.ground_albedo: must be finite");
}

TEST(AtmosphereModelTest, LayersMustLieInsideTheAtmosphere) {
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["absorber"]["density"]["width_m"] = 60000.0; }),
            "bad.json: atmosphere.absorber.density.width_m: the tent [-5000, 55000] m must lie "
            "inside the atmosphere [0, 100000] m");
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["mie"]["density"]["type"] = "gaussian"; }),
            "bad.json: atmosphere.mie.density.type: 'gaussian' is not a density profile "
            "(exponential, tent, uniform)");
}

TEST(AtmosphereModelTest, ExtinctionMustNotBeBelowScattering) {
  EXPECT_EQ(error_after([](nlohmann::json& a) {
              a["mie"]["extinction"] = {3e-6, 3e-6, 3e-6};
            }),
            "bad.json: atmosphere.mie.extinction: must not be below scattering");
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["spectrum"]["mie_extinction"]["value"] = 1e-6; }),
            "bad.json: atmosphere.spectrum.mie_extinction: must not be below mie_scattering (at "
            "380 nm)");
}

TEST(AtmosphereModelTest, RayleighAbsorptionBelongsToTheAbsorber) {
  EXPECT_EQ(error_after([](nlohmann::json& a) {
              a["rayleigh"]["absorption"] = {1e-7, 0, 0};
            }),
            "bad.json: atmosphere.rayleigh: absorption must be zero; give it as the absorber "
            "component");
}

TEST(AtmosphereModelTest, SpectrumNeedsEnoughIncreasingSamplesOverTheVisible) {
  EXPECT_EQ(error_after([](nlohmann::json& a) {
              a["spectrum"]["wavelengths_nm"] = {400, 500, 600};
            }),
            "bad.json: atmosphere.spectrum.wavelengths_nm: 3 samples; at least 16 are needed");
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["spectrum"]["wavelengths_nm"][5] = 380.0; }),
            "bad.json: atmosphere.spectrum.wavelengths_nm: must be strictly increasing");
  EXPECT_EQ(error_after([](nlohmann::json& a) {
              auto& w = a["spectrum"]["wavelengths_nm"];
              for (auto& x : w) x = x.get<double>() + 10.0;
            }),
            "bad.json: atmosphere.spectrum.wavelengths_nm: [390, 790] nm must span 380-780 nm");
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["spectrum"]["solar_irradiance"].erase(0); }),
            "bad.json: atmosphere.spectrum.solar_irradiance: must be an array of 21 numbers");
}

TEST(AtmosphereModelTest, UnknownKeysAreRejected) {
  EXPECT_EQ(error_after([](nlohmann::json& a) { a["rayleigh"]["scale_height_m"] = 8000.0; }),
            "bad.json: atmosphere.rayleigh.scale_height_m: unknown key");
  EXPECT_EQ(
      error_after([](nlohmann::json& a) { a["spectrum"]["rayleigh_scattering"]["slope"] = 4.0; }),
      "bad.json: atmosphere.spectrum.rayleigh_scattering.slope: unknown key");
}

TEST(AtmosphereModelTest, DenseVariantScalesScatteringOnly) {
  AtmosphereModel m = parse(earth_atmosphere());
  AtmosphereModel dense = with_scattering_scaled(m, 10.0);
  EXPECT_EQ(dense.rayleigh.scattering, 10.0 * m.rayleigh.scattering);
  EXPECT_EQ(dense.mie.scattering, 10.0 * m.mie.scattering);
  EXPECT_EQ(dense.mie.absorption, m.mie.absorption);
  EXPECT_EQ(dense.spectrum->rayleigh_scattering[0], 10.0 * m.spectrum->rayleigh_scattering[0]);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
