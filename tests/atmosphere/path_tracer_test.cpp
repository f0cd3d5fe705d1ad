// The ground truth checked against what it must reproduce: exact sampling
// (chi-square), single scattering against a deterministic quadrature,
// transmittance against the analytic answer, energy conservation (a
// furnace), and bit-identical renders at any thread count. Statistical
// tests use fixed seeds, so they pass or fail the same way every run.
#include "atmosphere/reference/path_tracer.h"
#include "atmosphere/scenes/scene.h"
#include "atmosphere/shared_math.h"
#include "sim/body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>

namespace planet {
namespace {

using reference::Rng;

AtmosphereModel earth_model() {
  Body body = load_body(find_body_file("earth"));
  return parse_atmosphere(JsonObject(body.atmosphere, body.file.string(), "atmosphere"));
}

// Pearson's chi-square of `samples` values of mu in [-1, 1] against the
// density pdf(mu) (over mu, integrating to 1), 50 equal bins; bins expected
// to hold fewer than 5 samples are pooled (as pbrt-v4's tests do). Returns
// the statistic and its degrees of freedom.
std::pair<double, int> chi_square(const std::function<double(Rng&)>& sample,
                                  const std::function<double(double)>& pdf, int samples) {
  const int bins = 50;
  std::vector<double> observed(bins, 0.0), expected(bins, 0.0);
  Rng rng(12345);
  for (int i = 0; i < samples; ++i) {
    double mu = sample(rng);
    int b = std::clamp(int((mu + 1.0) * 0.5 * bins), 0, bins - 1);
    observed[size_t(b)] += 1.0;
  }
  for (int b = 0; b < bins; ++b) {
    // Simpson's rule within the bin.
    const int n = 200;
    double lo = -1.0 + 2.0 * b / bins, h = 2.0 / bins / n, sum = 0;
    for (int k = 0; k <= n; ++k) {
      double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
      sum += w * pdf(lo + k * h);
    }
    expected[size_t(b)] = sum * h / 3.0 * samples;
  }
  double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
  int dof = -1;
  for (int b = 0; b < bins; ++b) {
    if (expected[size_t(b)] < 5.0) {
      pooled_observed += observed[size_t(b)];
      pooled_expected += expected[size_t(b)];
      continue;
    }
    double d = observed[size_t(b)] - expected[size_t(b)];
    chi2 += d * d / expected[size_t(b)];
    ++dof;
  }
  if (pooled_expected > 0) {
    double d = pooled_observed - pooled_expected;
    chi2 += d * d / std::max(pooled_expected, 1.0);
    ++dof;
  }
  return {chi2, dof};
}

// The chi-square value exceeded with probability 1e-3 (Wilson and
// Hilferty 1931's cube-root approximation, z = 3.09).
double chi_square_threshold(int dof) {
  double k = dof, a = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - a + 3.09 * std::sqrt(a), 3.0);
}

void expect_matches_pdf(const char* what, const std::function<double(Rng&)>& sample,
                        const std::function<double(double)>& pdf) {
  auto [chi2, dof] = chi_square(sample, pdf, 200000);
  EXPECT_LT(chi2, chi_square_threshold(dof)) << what << ": " << dof << " degrees of freedom";
}

TEST(PathTracerTest, PhaseSamplingMatchesThePhaseFunctions) {
  expect_matches_pdf(
      "rayleigh", [](Rng& r) { return reference::sample_rayleigh_mu(r.uniform()); },
      [](double mu) { return 2.0 * reference::kPi * shared::rayleigh_phase(mu); });
  for (double g : {-0.3, 0.0, 0.5, 0.8, 0.95}) {
    expect_matches_pdf(
        "henyey-greenstein",
        [g](Rng& r) { return reference::sample_henyey_greenstein_mu(g, r.uniform()); },
        [g](double mu) { return 2.0 * reference::kPi * shared::henyey_greenstein_phase(g, mu); });
    expect_matches_pdf(
        "cornette-shanks", [g](Rng& r) { return reference::sample_cornette_shanks_mu(g, r); },
        [g](double mu) { return 2.0 * reference::kPi * shared::cornette_shanks_phase(g, mu); });
  }
}

TEST(PathTracerTest, SunConeAndLambertSamplingMatchTheirPdfs) {
  glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.4, 0.8));
  double cos_alpha = std::cos(0.5);  // a wide cone, so that the bins see it
  expect_matches_pdf(
      "cone", [&](Rng& r) { return glm::dot(axis, reference::sample_cone(axis, cos_alpha, r)); },
      [&](double mu) { return mu >= cos_alpha ? 1.0 / (1.0 - cos_alpha) : 0.0; });
  expect_matches_pdf(
      "cosine", [&](Rng& r) { return glm::dot(axis, reference::sample_cosine(axis, r)); },
      [](double mu) { return mu > 0 ? 2.0 * mu : 0.0; });
  // The azimuth is uniform too: the mean direction of the cone is its axis.
  Rng rng(7);
  glm::dvec3 mean(0.0);
  for (int i = 0; i < 20000; ++i) mean += reference::sample_cone(axis, cos_alpha, rng);
  mean /= 20000.0;
  EXPECT_NEAR(glm::dot(glm::normalize(mean), axis), 1.0, 1e-3);
}

// Deterministic single scattering: midpoint rule along the view ray (4000
// steps), with the sun's transmittance by the trapezoid rule (400 steps)
// and zero inside the planet's shadow; a point sun.
double single_scattering_quadrature(const AtmosphereModel& model, int channel, glm::dvec3 o,
                                    glm::dvec3 d, glm::dvec3 sun) {
  shared::Atmosphere a = shared::to_shared(model);
  double t0, t1;
  if (!shared::ray_shell(o, d, model.bottom_radius, model.top_radius, t0, t1)) return 0.0;
  const int steps = 4000;
  double dt = (t1 - t0) / steps, tau = 0, radiance = 0;
  for (int i = 0; i < steps; ++i) {
    glm::dvec3 p = o + (t0 + (i + 0.5) * dt) * d;
    double r = glm::length(p), altitude = r - model.bottom_radius;
    double sigma_t = shared::extinction_at(a, altitude)[channel];
    double tau_mid = tau + 0.5 * sigma_t * dt;
    tau += sigma_t * dt;
    double mu_s = glm::dot(p, sun) / r;
    if (shared::ray_intersects_ground(a, r, mu_s)) continue;
    double sun_t = std::exp(-shared::optical_depth_to_top(a, r, mu_s, 400)[channel]);
    double nu = glm::dot(d, sun);
    double scattering =
        model.rayleigh.scattering[channel] * model.rayleigh.density.density(altitude) *
            shared::rayleigh_phase(nu) +
        model.mie.scattering[channel] * model.mie.density.density(altitude) *
            shared::cornette_shanks_phase(model.mie_g, nu);
    radiance += std::exp(-tau_mid) * scattering * sun_t * dt;
  }
  return radiance * model.solar_irradiance[channel];
}

TEST(PathTracerTest, SingleScatteringAgreesWithQuadrature) {
  AtmosphereModel model = earth_model();
  model.sun_angular_radius = 1e-5;  // the quadrature's point sun
  model.ground_albedo = 0.0;
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  TraceOptions order1;
  order1.max_order = 1;
  glm::dvec3 sun = glm::normalize(glm::dvec3(0.5, 0.0, std::sqrt(0.75)));  // 30 deg from zenith
  struct Case {
    const char* what;
    glm::dvec3 origin, dir;
  };
  auto dir = [](double zenith_deg, double azimuth_deg) {
    double z = glm::radians(zenith_deg), a = glm::radians(azimuth_deg);
    return glm::dvec3(std::sin(z) * std::cos(a), std::sin(z) * std::sin(a), std::cos(z));
  };
  const Case cases[] = {
      {"ground, 45 deg up, 90 deg from the sun", {0, 0, 6360e3 + 2.0}, dir(45, 90)},
      {"ground, near the horizon toward the sun", {0, 0, 6360e3 + 2.0}, dir(88, 0)},
      {"10 km up, looking down into shadowless air", {0, 0, 6370e3}, dir(120, 180)},
      {"from space through the limb, 15 km above the ground", {-7000e3, 0, 6375e3},
       glm::dvec3(1, 0, 0)},
  };
  for (const Case& c : cases) {
    for (int channel = 0; channel < 3; ++channel) {
      double expected = single_scattering_quadrature(model, channel, c.origin, c.dir, sun);
      RadianceEstimate e = estimate_radiance(medium, size_t(channel), c.origin, c.dir, sun, order1,
                                             20000, 99 + uint64_t(channel));
      EXPECT_LT(std::abs(e.mean - expected), 3.0 * e.std_error)
          << c.what << ", channel " << channel << ": path tracer " << e.mean << " +- "
          << e.std_error << ", quadrature " << expected;
      // The agreement means something only if the error bar is tight.
      EXPECT_LT(e.std_error, 0.03 * expected) << c.what;
    }
  }
}

TEST(PathTracerTest, RatioTrackingIsUnbiasedTransmittance) {
  AtmosphereModel model = earth_model();
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  shared::Atmosphere a = shared::to_shared(model);
  for (double zenith : {0.0, 60.0, 85.0}) {
    double mu = std::cos(glm::radians(zenith));
    glm::dvec3 o(0, 0, model.bottom_radius + 1.0), d(std::sqrt(1 - mu * mu), 0, mu);
    for (int channel = 0; channel < 3; ++channel) {
      double expected =
          std::exp(-shared::optical_depth_to_top(a, glm::length(o), mu, 20000)[channel]);
      Rng rng(5 + uint64_t(channel));
      double mean = 0, m2 = 0;
      const int n = 20000;
      for (int i = 0; i < n; ++i) {
        double x = ratio_tracking_transmittance(medium, medium.channels[size_t(channel)], o, d, rng);
        double delta = x - mean;
        mean += delta / (i + 1);
        m2 += delta * (x - mean);
      }
      double std_error = std::sqrt(m2 / (n - 1) / n);
      EXPECT_LT(std::abs(mean - expected), 3.0 * std_error + 1e-12)
          << "zenith " << zenith << " channel " << channel << ": " << mean << " vs " << expected;
    }
  }
}

ReferenceImage furnace(double ground_albedo, double scattering_scale, glm::dvec3 camera,
                       glm::dvec3 forward) {
  AtmosphereModel model = with_scattering_scaled(earth_model(), scattering_scale);
  model.mie.absorption = glm::dvec3(0.0);
  model.absorber.absorption = glm::dvec3(0.0);
  model.ground_albedo = ground_albedo;
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  ReferenceView view;
  view.width = 16;
  view.height = 8;
  view.camera_atmo = camera;
  // A 90 degree view around `forward`, with any up.
  glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.3, 0.1, 1.0)));
  glm::dvec3 up = glm::cross(right, forward);
  view.ray_from_ndc = glm::dmat3(2.0 * right, up, forward);
  ReferenceSettings settings;
  settings.spp = 6;
  settings.seed = 3;
  settings.trace.sun = false;
  settings.trace.environment_radiance = 1.0;
  return render_reference(medium, view, settings);
}

TEST(PathTracerTest, WhiteFurnaceLosesNoEnergy) {
  // Radiance 1 from every direction outside a purely scattering atmosphere
  // over a white ground: in equilibrium every ray sees radiance 1, whatever
  // the number of scattering orders. Each path carries weight 1 until it
  // escapes, so a lost path (a wrong roulette, a ray trapped below the
  // ground, an absorption that is not there) shows as a pixel below 1.
  glm::dvec3 ground(0, 0, 6360e3 + 2.0), space(0, -8000e3, 0);
  for (double scale : {1.0, 50.0}) {
    for (auto [camera, forward] : {std::pair{ground, glm::dvec3(0.6, 0, 0.8)},
                                   std::pair{ground, glm::dvec3(0.8, 0, -0.6)},
                                   std::pair{space, glm::dvec3(0, 1, 0)}}) {
      ReferenceImage image = furnace(1.0, scale, camera, forward);
      for (float v : image.rgb) ASSERT_NEAR(v, 1.0f, 1e-6f) << "scattering x" << scale;
    }
  }
  // And the check can fail: a grey ground does absorb, so rays that can
  // reach it see less than 1.
  ReferenceImage grey = furnace(0.5, 1.0, ground, glm::dvec3(0.8, 0, -0.6));
  double mean = 0;
  for (float v : grey.rgb) mean += v / double(grey.rgb.size());
  EXPECT_LT(mean, 0.9);
}

TEST(PathTracerTest, SameBitsAtOneAndTwoThreads) {
  Scene scene = find_scene("earth_sunset");
  scene.width = 24;
  scene.height = 12;
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  for (ReferenceMode mode : {ReferenceMode::kRgb, ReferenceMode::kSpectral}) {
    Medium medium = make_medium(model, mode);
    ReferenceSettings settings;
    settings.spp = int(medium.channels.size());
    settings.seed = scene.seed();
    settings.threads = 1;
    ReferenceImage one = render_reference(medium, reference_view(scene, body, model), settings);
    settings.threads = 2;
    ReferenceImage two = render_reference(medium, reference_view(scene, body, model), settings);
    ASSERT_EQ(one.rgb.size(), two.rgb.size());
    EXPECT_EQ(0, std::memcmp(one.rgb.data(), two.rgb.data(), one.rgb.size() * sizeof(float)))
        << to_string(mode);
  }
}

TEST(PathTracerTest, ViewRaysAreFrameRendererRays) {
  // The centre pixel's ray is the camera's forward axis, and the top row
  // looks up: rows run top-down as in the EXR files.
  Scene scene = find_scene("earth_noon");
  scene.width = 3;
  scene.height = 3;
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  ReferenceView view = reference_view(scene, body, model);
  glm::dvec3 scale = glm::normalize(view.camera_atmo);
  glm::dvec3 forward = glm::normalize(scene.camera.forward_body());
  // Atmosphere space stretches z by a/b = 1.0034, turning rays by < 3e-3 rad.
  EXPECT_NEAR(glm::dot(view.ray_dir(1, 1), forward), 1.0, 1e-5 + 5e-6);
  EXPECT_GT(glm::dot(view.ray_dir(1, 0), scale), glm::dot(view.ray_dir(1, 2), scale));
}

}  // namespace
}  // namespace planet
