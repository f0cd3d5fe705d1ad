// The oneil technique's math (atmosphere/shaders/oneil_functions.glsl as
// C++ double, atmosphere/math/oneil_math.h): the scale function fitted to
// each shipped body against the exact optical depth, and single scattering
// along a ray against a brute-force integral.
#include "atmosphere/math/oneil_math.h"

#include "sim/body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

using shared::Atmosphere;
using shared::Real3;

AtmosphereModel body_model(const std::string& name) {
  return load_atmosphere(load_body(find_body_file(name)));
}

// The truth the fit is measured against, itself against the closed form of
// the exponential layer (shared math; 1e-5 on Earth's Rayleigh layer).
TEST(OneilMathTest, ExactColumnMatchesTheClosedForm) {
  Atmosphere a = shared::to_shared(body_model("earth"));
  for (double h : {0.0, 5e3, 40e3, 90e3}) {
    double r = a.bottom_radius + h;
    for (double zenith_deg : {0.0, 45.0, 80.0, 89.0, 90.0, 93.0}) {
      double mu = std::cos(glm::radians(zenith_deg));
      if (shared::ray_intersects_ground(a, r, mu)) continue;
      double exact = oneil::exact_column(a, 8000.0, r, mu);
      double closed = shared::exponential_optical_depth_to_top(a, 8000.0, r, mu);
      EXPECT_NEAR(exact / closed, 1.0, 2e-5) << "h " << h << " zenith " << zenith_deg;
    }
  }
}

// The goal: the fitted scale function within 1 % of the exact
// optical depth over heights 0 to the top and every ray that misses the
// ground, for each body's Rayleigh and Mie layers. Measured: Earth 0.76 /
// 0.42 %, Mars 0.73 / 0.72 %, the asteroid 0.34 / 0.74 %.
TEST(OneilMathTest, FittedScaleIsWithinOnePercentOnEveryBody) {
  for (const char* name : {"earth", "mars", "asteroid"}) {
    oneil::BodyScales s = oneil::fit_body_scales(body_model(name));
    std::printf("%s: worst relative optical-depth error %.3f %% Rayleigh, %.3f %% Mie\n", name,
                100 * s.rayleigh_error.worst_relative, 100 * s.mie_error.worst_relative);
    EXPECT_LE(s.rayleigh_error.worst_relative, 0.01) << name;
    EXPECT_LE(s.mie_error.worst_relative, 0.01) << name;
  }
}

// The chapter's polynomial on its own case (H a quarter of the thickness,
// the thickness 2.5 % of the radius), from the ground, where it was fitted:
// within 2 % up to 80 deg from the zenith (measured 1.6 %) and 5 % to the
// horizon (measured 2.4 %). Over the whole domain it fails near the top,
// where the shell ends and it does not; the fitted form there holds 1 %.
TEST(OneilMathTest, ChapterPolynomialFitsItsOwnCaseFromTheGround) {
  Atmosphere a{};
  a.bottom_radius = 6.4e6;
  a.top_radius = 1.025 * a.bottom_radius;
  const double H = 0.25 * (a.top_radius - a.bottom_radius);
  oneil::OneilScale chapter = oneil::chapter_scale(H);
  double worst_80 = 0, worst_90 = 0;
  for (int k = 0; k <= 900; ++k) {
    double zenith_deg = 0.1 * k;
    double mu = std::cos(glm::radians(zenith_deg));
    double exact = oneil::exact_column(a, H, a.bottom_radius, mu);
    double error = std::abs(oneil::oneil_column(a, chapter, a.bottom_radius, mu) / exact - 1.0);
    if (zenith_deg <= 80.0) worst_80 = std::max(worst_80, error);
    worst_90 = std::max(worst_90, error);
  }
  std::printf("chapter's case from the ground: %.3f %% to 80 deg, %.3f %% to 90 deg\n",
              100 * worst_80, 100 * worst_90);
  EXPECT_LT(worst_80, 0.02);
  EXPECT_LT(worst_90, 0.05);
  EXPECT_GT(oneil::measure_scale_error(a, chapter).worst_relative, 0.1);
  EXPECT_LE(oneil::measure_scale_error(a, oneil::fit_scale(a, H)).worst_relative, 0.01);
}

// On Mars and the asteroid, whose ratios of scale height to thickness are
// not the chapter's, the fitted function is closer everywhere it matters.
TEST(OneilMathTest, FittedScaleBeatsTheChaptersOnMarsAndTheAsteroid) {
  for (const char* name : {"mars", "asteroid"}) {
    AtmosphereModel model = body_model(name);
    Atmosphere a = shared::to_shared(model);
    oneil::BodyScales s = oneil::fit_body_scales(model);
    for (const oneil::OneilScale* fitted : {&s.rayleigh, &s.mie}) {
      oneil::ScaleError chapter =
          oneil::measure_scale_error(a, oneil::chapter_scale(fitted->scale_height));
      oneil::ScaleError own = oneil::measure_scale_error(a, *fitted);
      EXPECT_LT(own.worst_relative, chapter.worst_relative) << name;
      EXPECT_LT(own.worst_of_vertical, chapter.worst_of_vertical) << name;
    }
  }
}

// Single scattering (Rayleigh and Mie apart, per unit phase function) along
// Earth rays against a brute-force integral: 4000 trapezoid steps along the
// ray, the optical depth to the camera accumulated on the way and the one
// to the sun by the shared quadrature (400 steps). No absorber: O'Neil's
// model has none. 16 samples: measured within 1.3 % for Rayleigh and 2.6 %
// for Mie (whose 1.2 km layer is thin against 16 samples spread over rays
// of hundreds of km) and 0.5 % in optical depth (the fit's error); the
// bounds leave a third more.
TEST(OneilMathTest, SingleScatteringMatchesABruteForceIntegral) {
  AtmosphereModel model = body_model("earth");
  model.absorber.absorption = glm::dvec3(0.0);
  Atmosphere a = shared::to_shared(model);
  oneil::BodyScales s = oneil::fit_body_scales(model);
  // In the x-z plane, 30 deg over the camera's horizon.
  const Real3 sun =
      glm::normalize(Real3(std::cos(glm::radians(30.0)), 0.0, std::sin(glm::radians(30.0))));
  struct Ray {
    double height, elevation_deg, azimuth_deg;
  };
  for (const Ray& ray : {Ray{1.0, 10.0, 0.0}, Ray{1.0, 45.0, 120.0}, Ray{1000.0, 1.0, 60.0},
                         Ray{20e3, -2.0, 180.0}, Ray{5e3, -30.0, 30.0}}) {
    Real3 o(0.0, 0.0, a.bottom_radius + ray.height);
    double e = glm::radians(ray.elevation_deg), az = glm::radians(ray.azimuth_deg);
    Real3 d(std::cos(e) * std::cos(az), std::cos(e) * std::sin(az), std::sin(e));
    double t_near, t_far, g_near, g_far;
    shared::ray_sphere(o, d, a.top_radius, t_near, t_far);
    bool ground = shared::ray_sphere(o, d, a.bottom_radius, g_near, g_far) && g_near > 0;
    double t_end = ground ? g_near : t_far;
    Real3 rayleigh, mie, transmittance;
    oneil::oneil_single_scattering(a, s.rayleigh, s.mie, o, d, ground, 0.0, t_end, sun, 16,
                                   rayleigh, mie, transmittance);
    const int steps = 4000;
    double dt = t_end / steps;
    Real3 sum_r(0.0), sum_m(0.0), depth(0.0), previous_extinction(0.0);
    for (int i = 0; i <= steps; ++i) {
      Real3 p = o + (i * dt) * d;
      double r = glm::length(p), h = r - a.bottom_radius;
      Real3 extinction = shared::extinction_at(a, h);
      if (i > 0) depth += 0.5 * (extinction + previous_extinction) * dt;
      previous_extinction = extinction;
      double mu_s = glm::dot(p, sun) / r;
      if (shared::ray_intersects_ground(a, r, mu_s)) continue;
      Real3 attenuation = glm::exp(-(depth + shared::optical_depth_to_top(a, r, mu_s, 400)));
      double w = (i == 0 || i == steps) ? 0.5 : 1.0;
      sum_r += w * shared::profile_density(a.rayleigh_density, h) * attenuation * dt;
      sum_m += w * shared::profile_density(a.mie_density, h) * attenuation * dt;
    }
    Real3 brute_r = sum_r * a.rayleigh_scattering * a.solar_irradiance;
    Real3 brute_m = sum_m * a.mie_scattering * a.solar_irradiance;
    std::printf(
        "height %g elevation %g: light / brute force %.4f %.4f (Rayleigh, blue; Mie), "
        "optical depth %.4f\n",
        ray.height, ray.elevation_deg, rayleigh.b / brute_r.b, mie.b / brute_m.b,
        -std::log(transmittance.b) / depth.b);
    for (int c = 0; c < 3; ++c) {
      SCOPED_TRACE(testing::Message() << "height " << ray.height << " elevation "
                                      << ray.elevation_deg << " channel " << c);
      EXPECT_NEAR(rayleigh[c] / brute_r[c], 1.0, 0.02);
      EXPECT_NEAR(mie[c] / brute_m[c], 1.0, 0.035);
      EXPECT_NEAR(-std::log(transmittance[c]) / depth[c], 1.0, 0.007);
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
