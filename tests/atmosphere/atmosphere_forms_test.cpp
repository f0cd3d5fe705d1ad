// The model (atmosphere/model.h) and the forms the code reads it in: the
// shared math's Atmosphere (shared::to_shared) and the path tracer's Medium
// (make_medium). Every field of the model lands where it belongs, and every
// field of each form comes from the model (the std140 block's test is
// atmosphere_block_gl_test.cpp: the block lives with the GPU code). The
// structured bindings name every field of each form, so a field added to a
// form or to the model fails to compile here until it is checked.
#include "atmosphere/math/shared_math.h"
#include "atmosphere/reference/medium.h"
#include "atmosphere/spectrum.h"
#include "tests/atmosphere/distinct_atmosphere.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

using forms::distinct_model;

void expect_same_profile(const DensityProfile& form, const DensityProfile& model,
                         const char* what) {
  for (int k = 0; k < 2; ++k) {
    const auto& [width, exp_term, exp_scale, linear_term, constant_term] = form.layers[k];
    const DensityLayer& m = model.layers[k];
    EXPECT_EQ(width, m.width) << what << " layer " << k;
    EXPECT_EQ(exp_term, m.exp_term) << what << " layer " << k;
    EXPECT_EQ(exp_scale, m.exp_scale) << what << " layer " << k;
    EXPECT_EQ(linear_term, m.linear_term) << what << " layer " << k;
    EXPECT_EQ(constant_term, m.constant_term) << what << " layer " << k;
  }
}

TEST(AtmosphereFormsTest, EveryModelFieldReachesTheSharedAtmosphere) {
  for (MiePhase phase : {MiePhase::kCornetteShanks, MiePhase::kHenyeyGreenstein}) {
    const AtmosphereModel m = distinct_model(phase);
    // The model's fields; wavelengths_nm and spectrum reach no shader (the
    // shaders draw the three RGB coefficients whatever their wavelengths).
    const auto& [bottom_radius, top_radius, wavelengths_nm, solar_irradiance, sun_angular_radius,
                 mie_g, mie_phase, ground_albedo, rayleigh, mie, absorber, spectrum] = m;
    const auto& [a_bottom_radius, a_top_radius, a_solar_irradiance, a_sun_angular_radius,
                 a_rayleigh_scattering, a_rayleigh_density, a_mie_scattering, a_mie_extinction,
                 a_mie_g, a_mie_density, a_absorption_extinction, a_absorption_density,
                 a_ground_albedo, a_mie_phase_hg] = shared::to_shared(m);
    EXPECT_EQ(a_bottom_radius, bottom_radius);
    EXPECT_EQ(a_top_radius, top_radius);
    EXPECT_EQ(a_solar_irradiance, solar_irradiance);
    EXPECT_EQ(a_sun_angular_radius, sun_angular_radius);
    EXPECT_EQ(a_rayleigh_scattering, rayleigh.scattering);
    expect_same_profile(a_rayleigh_density, rayleigh.density, "rayleigh");
    EXPECT_EQ(a_mie_scattering, mie.scattering);
    EXPECT_EQ(a_mie_extinction, mie.scattering + mie.absorption);
    EXPECT_EQ(a_mie_g, mie_g);
    expect_same_profile(a_mie_density, mie.density, "mie");
    // The absorber scatters nothing the shaders follow: what it takes out
    // of a ray, scattering or absorption, is lost to it.
    EXPECT_EQ(a_absorption_extinction, absorber.scattering + absorber.absorption);
    expect_same_profile(a_absorption_density, absorber.density, "absorber");
    EXPECT_EQ(a_ground_albedo, ground_albedo);
    EXPECT_EQ(a_mie_phase_hg, mie_phase == MiePhase::kHenyeyGreenstein ? 1.0 : 0.0);
  }
}

// The medium's shell, phase function and profiles: the model's in both modes.
void expect_medium_shell(const Medium& medium, const AtmosphereModel& m) {
  const auto& [bottom_radius, top_radius, mie_g, mie_phase, sun_angular_radius, rayleigh_density,
               mie_density, absorber_density, channels] = medium;
  EXPECT_EQ(bottom_radius, m.bottom_radius);
  EXPECT_EQ(top_radius, m.top_radius);
  EXPECT_EQ(mie_g, m.mie_g);
  EXPECT_EQ(mie_phase, m.mie_phase);
  EXPECT_EQ(sun_angular_radius, m.sun_angular_radius);
  expect_same_profile(rayleigh_density, m.rayleigh.density, "rayleigh");
  expect_same_profile(mie_density, m.mie.density, "mie");
  expect_same_profile(absorber_density, m.absorber.density, "absorber");
}

TEST(AtmosphereFormsTest, EveryModelFieldReachesTheMediumInRgb) {
  for (MiePhase phase : {MiePhase::kCornetteShanks, MiePhase::kHenyeyGreenstein}) {
    const AtmosphereModel m = distinct_model(phase);
    const Medium medium = make_medium(m, ReferenceMode::kRgb);
    expect_medium_shell(medium, m);
    ASSERT_EQ(medium.channels.size(), 3u);
    for (int i = 0; i < 3; ++i) {
      const auto& [wavelength_nm, rayleigh_scattering, mie_scattering, mie_absorption,
                   absorber_absorption, solar_irradiance, ground_albedo, rgb_weight] =
          medium.channels[size_t(i)];
      EXPECT_EQ(wavelength_nm, m.wavelengths_nm[i]) << "channel " << i;
      EXPECT_EQ(rayleigh_scattering, m.rayleigh.scattering[i]) << "channel " << i;
      EXPECT_EQ(mie_scattering, m.mie.scattering[i]) << "channel " << i;
      EXPECT_EQ(mie_absorption, m.mie.absorption[i]) << "channel " << i;
      EXPECT_EQ(absorber_absorption, m.absorber.scattering[i] + m.absorber.absorption[i])
          << "channel " << i;
      EXPECT_EQ(solar_irradiance, m.solar_irradiance[i]) << "channel " << i;
      EXPECT_EQ(ground_albedo, m.ground_albedo[i]) << "channel " << i;
      glm::dvec3 own(0.0);
      own[i] = 1.0;
      EXPECT_EQ(rgb_weight, own) << "channel " << i;
    }
  }
}

TEST(AtmosphereFormsTest, EverySpectralSampleReachesTheMedium) {
  AtmosphereModel m = distinct_model(MiePhase::kHenyeyGreenstein, 5);
  const AtmosphereSpectrum& s = *m.spectrum;
  const Medium medium = make_medium(m, ReferenceMode::kSpectral);
  expect_medium_shell(medium, m);
  const std::vector<glm::dvec3> weights = srgb_weights(s.wavelengths_nm);
  ASSERT_EQ(medium.channels.size(), s.wavelengths_nm.size());
  for (size_t i = 0; i < medium.channels.size(); ++i) {
    const auto& [wavelength_nm, rayleigh_scattering, mie_scattering, mie_absorption,
                 absorber_absorption, solar_irradiance, ground_albedo, rgb_weight] =
        medium.channels[i];
    EXPECT_EQ(wavelength_nm, s.wavelengths_nm[i]) << "sample " << i;
    EXPECT_EQ(rayleigh_scattering, s.rayleigh_scattering[i]) << "sample " << i;
    EXPECT_EQ(mie_scattering, s.mie_scattering[i]) << "sample " << i;
    EXPECT_EQ(mie_absorption, s.mie_absorption[i]) << "sample " << i;
    EXPECT_EQ(absorber_absorption, s.absorber_absorption[i]) << "sample " << i;
    EXPECT_EQ(solar_irradiance, s.solar_irradiance[i]) << "sample " << i;
    EXPECT_EQ(ground_albedo, s.ground_albedo[i]) << "sample " << i;
    EXPECT_EQ(rgb_weight, weights[i]) << "sample " << i;
  }
  // A spectrum without the ground's albedo: the RGB albedo's green, grey.
  m.spectrum->ground_albedo.clear();
  for (const MediumChannel& c : make_medium(m, ReferenceMode::kSpectral).channels) {
    EXPECT_EQ(c.ground_albedo, m.ground_albedo.g);
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
