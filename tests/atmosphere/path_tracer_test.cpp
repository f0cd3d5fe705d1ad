// The ground truth checked against what it must reproduce: exact sampling
// (chi-square), stratification of its scrambled pairs, single scattering
// against a deterministic quadrature, the column table against direct
// integration, energy conservation (a furnace), and bit-identical renders
// at any thread count. Statistical
// tests use fixed seeds, so they pass or fail the same way every run.
#include "atmosphere/math/shared_math.h"
#include "atmosphere/reference/reference_render.h"
#include "core/error.h"
#include "lab/scene.h"
#include "sim/body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

using reference::Rng;

AtmosphereModel earth_model() {
  Body body = load_body(find_body_file("earth"));
  return load_atmosphere(body);
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
    double scattering = model.rayleigh.scattering[channel] *
                            density_at(model.rayleigh.density, altitude) *
                            shared::rayleigh_phase(nu) +
                        model.mie.scattering[channel] * density_at(model.mie.density, altitude) *
                            shared::cornette_shanks_phase(model.mie_g, nu);
    radiance += std::exp(-tau_mid) * scattering * sun_t * dt;
  }
  return radiance * model.solar_irradiance[channel];
}

TEST(PathTracerTest, SingleScatteringAgreesWithQuadrature) {
  AtmosphereModel model = earth_model();
  model.sun_angular_radius = 1e-5;  // the quadrature's point sun
  model.ground_albedo = glm::dvec3(0.0);
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  const ColumnTable table(medium);
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
      {"from space through the limb, 15 km above the ground",
       {-7000e3, 0, 6375e3},
       glm::dvec3(1, 0, 0)},
  };
  for (const Case& c : cases) {
    for (int channel = 0; channel < 3; ++channel) {
      double expected = single_scattering_quadrature(model, channel, c.origin, c.dir, sun);
      RadianceEstimate e = estimate_radiance(table, size_t(channel), c.origin, c.dir, sun, order1,
                                             20000, 99 + uint64_t(channel));
      EXPECT_LT(std::abs(e.mean - expected), 3.0 * e.std_error)
          << c.what << ", channel " << channel << ": path tracer " << e.mean << " +- "
          << e.std_error << ", quadrature " << expected;
      // The agreement means something only if the error bar is tight.
      EXPECT_LT(e.std_error, 0.03 * expected) << c.what;
    }
  }
}

// Columns by a 100000-step midpoint rule along the ray: slow and plain.
glm::dvec3 midpoint_columns(const Medium& m, double r, double mu) {
  double d = -r * mu + std::sqrt(r * r * (mu * mu - 1.0) + m.top_radius * m.top_radius);
  const int steps = 100000;
  double dt = d / steps;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < steps; ++i) {
    double t = (i + 0.5) * dt;
    double h = std::sqrt(r * r + t * t + 2.0 * r * t * mu) - m.bottom_radius;
    sum += dt * glm::dvec3(density_at(m.rayleigh_density, h), density_at(m.mie_density, h),
                           density_at(m.absorber_density, h));
  }
  return sum;
}

TEST(PathTracerTest, ColumnTableMatchesDirectIntegration) {
  for (const char* body_name : {"earth", "mars"}) {
    Body body = load_body(find_body_file(body_name));
    AtmosphereModel model = load_atmosphere(body);
    Medium medium = make_medium(model, ReferenceMode::kRgb);
    const ColumnTable table(medium);
    std::vector<DepthTable> depths;
    for (const MediumChannel& c : medium.channels) depths.emplace_back(table, c);
    Rng rng(17);
    double worst_rule = 0, worst_table = 0, sum_sq = 0, worst_depth = 0, depth_sum_sq = 0;
    int n = 0;
    for (int i = 0; i < 2000; ++i) {
      // Heights packed toward the ground, half the rays near the horizon.
      double r = medium.bottom_radius +
                 (medium.top_radius - medium.bottom_radius) * std::pow(rng.uniform(), 3.0);
      double ratio = medium.bottom_radius / r;
      double horizon = -std::sqrt(1.0 - ratio * ratio);
      double mu = i % 2 ? horizon + (1.0 - horizon) * std::pow(rng.uniform(), 4.0)
                        : horizon + (1.0 - horizon) * rng.uniform();
      glm::dvec3 rule = table.integrate_to_top(r, mu), lookup = table.to_top(r, mu);
      glm::dvec3 plain = i < 40 ? midpoint_columns(medium, r, mu) : rule;
      for (size_t k = 0; k < medium.channels.size(); ++k) {
        const MediumChannel& c = medium.channels[k];
        double tau = optical_depth(c, rule);
        if (tau > 30.0) continue;  // transmittance below 1e-13: nothing to see
        worst_rule = std::max(worst_rule, std::abs(tau - optical_depth(c, plain)));
        double d = optical_depth(c, lookup) - tau;
        worst_table = std::max(worst_table, std::abs(d));
        sum_sq += d * d;
        double dd = depths[k].to_top(r, mu) - tau;
        worst_depth = std::max(worst_depth, std::abs(dd));
        depth_sum_sq += dd * dd;
        ++n;
      }
    }
    // Optical depth errors are relative errors of the transmittance.
    EXPECT_LT(worst_rule, 2e-6) << body_name << ": Gauss-Legendre against the midpoint rule";
    EXPECT_LT(std::sqrt(sum_sq / n), 2e-5) << body_name << ": table RMS";
    EXPECT_LT(worst_table, 4e-4) << body_name << ": table worst";
    EXPECT_LT(std::sqrt(depth_sum_sq / n), 2e-5) << body_name << ": depth table RMS";
    EXPECT_LT(worst_depth, 4e-4) << body_name << ": depth table worst";
    std::printf("%s: optical depth error RMS %.2g (columns) %.2g (depths), worst %.2g %.2g\n",
                body_name, std::sqrt(sum_sq / n), std::sqrt(depth_sum_sq / n), worst_table,
                worst_depth);
  }
}

TEST(PathTracerTest, PathBudgetsSpreadOverLanes) {
  // In all: path s of a pixel goes to lane s % 6 (2 replicates x 3 channels).
  EXPECT_EQ(PathBudget(14).lane_paths(3), (std::vector<int>{3, 3, 2, 2, 2, 2}));
  // Per channel: lanes are replicate-major, each channel split over both.
  PathBudget per_channel = PathBudget::parse("4,10,7");
  EXPECT_EQ(per_channel.spp, 21);
  EXPECT_EQ(per_channel.label(), "4,10,7");
  EXPECT_EQ(per_channel.lane_paths(3), (std::vector<int>{2, 5, 4, 2, 5, 3}));
  EXPECT_EQ(PathBudget::parse("98304"), PathBudget(98304));
  for (const char* bad : {"", "12x", "0", "-6", "4,,4", "4,", "99999999999", " 5", "+5", "4, 4"}) {
    EXPECT_THROW(PathBudget::parse(bad), InputError) << bad;
  }
  EXPECT_THROW(PathBudget(5).lane_paths(3), InputError);               // a lane with none
  EXPECT_THROW(PathBudget::parse("4,4").lane_paths(3), InputError);    // channels
  EXPECT_THROW(PathBudget::parse("4,1,4").lane_paths(3), InputError);  // a replicate with none
}

TEST(PathTracerTest, StratifiedPairsFillEveryElementaryInterval) {
  // The first 256 points of a scrambled (0, 2)-sequence are a (0, 8, 2)-net:
  // every box of 2^-a by 2^-(8-a) holds exactly one of them.
  for (uint64_t seed : {1ull, 99ull}) {
    std::vector<glm::dvec2> points;
    for (uint32_t i = 0; i < 256; ++i) points.push_back(reference::stratified_pair(i, seed));
    for (int a = 0; a <= 8; ++a) {
      std::vector<int> boxes(256, 0);
      for (const glm::dvec2& p : points) {
        int bx = int(p.x * (1 << a)), by = int(p.y * (1 << (8 - a)));
        ++boxes[size_t(bx * (1 << (8 - a)) + by)];
      }
      EXPECT_EQ(*std::min_element(boxes.begin(), boxes.end()), 1) << "a = " << a;
      EXPECT_EQ(*std::max_element(boxes.begin(), boxes.end()), 1) << "a = " << a;
    }
  }
  // Different seeds scramble differently.
  EXPECT_NE(reference::stratified_pair(5, 1).x, reference::stratified_pair(5, 2).x);
}

ReferenceImage furnace(double ground_albedo, double scattering_scale, glm::dvec3 camera,
                       glm::dvec3 forward) {
  AtmosphereModel model = with_scattering_scaled(earth_model(), scattering_scale);
  model.mie.absorption = glm::dvec3(0.0);
  model.absorber.absorption = glm::dvec3(0.0);
  model.ground_albedo = glm::dvec3(ground_albedo);
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  ReferenceView view;
  view.width = 8;
  view.height = 4;
  view.camera_atmo = camera;
  // A 90 degree view around `forward`, with any up.
  glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.3, 0.1, 1.0)));
  glm::dvec3 up = glm::cross(right, forward);
  view.ray_from_ndc = glm::dmat3(2.0 * right, up, forward);
  ReferenceSettings settings;
  settings.paths = 2 * 3 * 64;
  settings.seed = 3;
  settings.trace.sun = false;
  settings.trace.environment_radiance = 1.0;
  return render_reference(medium, view, settings);
}

TEST(PathTracerTest, WhiteFurnaceLosesNoEnergy) {
  // Radiance 1 from every direction outside a purely scattering atmosphere
  // over a white ground: in equilibrium every ray sees radiance 1, whatever
  // the number of scattering orders. Paths carry weights (forced
  // collisions, roulette), so each pixel is 1 within its own noise; a lost
  // path (a wrong roulette, a ray trapped below the ground, an absorption
  // that is not there) or a weight that forgets a probability shows as a
  // pixel off by many standard errors, and the whole image as well.
  glm::dvec3 ground(0, 0, 6360e3 + 2.0), space(0, -8000e3, 0);
  for (double scale : {1.0, 50.0}) {
    for (auto [camera, forward] :
         {std::pair{ground, glm::dvec3(0.6, 0, 0.8)}, std::pair{ground, glm::dvec3(0.8, 0, -0.6)},
          std::pair{space, glm::dvec3(0, 1, 0)}}) {
      ReferenceImage image = furnace(1.0, scale, camera, forward);
      // Each pixel's standard error comes from two replicates, too rough
      // to judge a pixel by; their mean square over the image is not.
      double sum = 0, variance = 0;
      for (size_t i = 0; i < image.rgb.size(); ++i) {
        sum += image.rgb[i];
        variance += double(image.noise[i]) * image.noise[i];
      }
      double n = double(image.rgb.size()), pixel_noise = std::sqrt(variance / n);
      EXPECT_LT(pixel_noise, 0.02) << "the check needs a tight error bar";
      EXPECT_LT(std::abs(sum / n - 1.0), 4.0 * std::sqrt(variance) / n + 1e-6)
          << "scattering x" << scale;
      for (size_t i = 0; i < image.rgb.size(); ++i) {
        ASSERT_LT(std::abs(image.rgb[i] - 1.0), 6.0 * pixel_noise + 1e-6)
            << "scattering x" << scale << ", value " << i;
      }
    }
  }
  // And the check can fail: a grey ground does absorb, so rays that can
  // reach it see less than 1.
  ReferenceImage grey = furnace(0.5, 1.0, ground, glm::dvec3(0.8, 0, -0.6));
  double mean = 0;
  for (float v : grey.rgb) mean += v / double(grey.rgb.size());
  EXPECT_LT(mean, 0.9);
}

// Earth at sunset, as the tracer sees it, at a test's size.
struct SunsetView {
  Scene scene;
  AtmosphereModel model;
  ReferenceView view;
};
SunsetView sunset_view(int width, int height) {
  SunsetView v;
  v.scene = find_scene("earth_sunset");
  v.scene.width = width;
  v.scene.height = height;
  Body body = scene_body(v.scene);
  v.model = scene_atmosphere(v.scene, body);
  v.view = reference_view(v.scene, body, v.model);
  return v;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(PathTracerTest, SameBitsAtOneAndTwoThreads) {
  SunsetView v = sunset_view(24, 12);
  for (ReferenceMode mode : {ReferenceMode::kRgb, ReferenceMode::kSpectral}) {
    Medium medium = make_medium(v.model, mode);
    ReferenceSettings settings;
    settings.paths = kReplicates * int(medium.channels.size());
    settings.seed = v.scene.seed();
    settings.threads = 1;
    ReferenceImage one = render_reference(medium, v.view, settings);
    settings.threads = 2;
    ReferenceImage two = render_reference(medium, v.view, settings);
    EXPECT_TRUE(same_bits(one.rgb, two.rgb)) << to_string(mode);
  }
}

TEST(PathTracerTest, RenderThatStopsAndGoesOnGivesTheSameBits) {
  // A render in chunks, started from the sums of a smaller budget that
  // itself stopped after each chunk, ends with the bits of a render of the
  // whole budget at once: what lets a reference too long for one sitting
  // be made in several.
  SunsetView v = sunset_view(6, 3);
  Medium medium = make_medium(v.model, ReferenceMode::kRgb);
  const ReferenceView& view = v.view;
  ReferenceSettings whole;
  whole.paths = PathBudget({40, 12, 90});
  whole.seed = v.scene.seed();
  whole.chunk_paths = 1000;
  ReferenceImage at_once = render_reference(medium, view, whole);

  ReferenceSettings small = whole;
  small.paths = PathBudget({20, 12, 30});
  small.chunk_paths = 4;
  std::vector<RenderSums> checkpoints;
  small.checkpoint = [&](const RenderSums& sums) { checkpoints.push_back(sums); };
  render_reference(medium, view, small);
  ASSERT_EQ(checkpoints.size(), 4u) << "15 paths in the largest lane, 4 at a time";
  EXPECT_EQ(checkpoints[0].done, (std::vector<int>{4, 4, 4, 4, 4, 4}));
  EXPECT_EQ(checkpoints.back().done, (std::vector<int>{10, 6, 15, 10, 6, 15}));

  ReferenceSettings rest = whole;
  rest.chunk_paths = 7;
  rest.start = &checkpoints.back();
  ReferenceImage went_on = render_reference(medium, view, rest);
  EXPECT_EQ(went_on.paths, 18u * (142 - 62)) << "only the paths not yet traced";
  EXPECT_TRUE(same_bits(at_once.rgb, went_on.rgb));
  EXPECT_TRUE(same_bits(at_once.noise, went_on.noise));

  // Sums with more paths in a lane than the budget gives it cannot be
  // gone on from.
  ReferenceSettings fewer = whole;
  fewer.paths = PathBudget({20, 12, 20});
  fewer.start = &checkpoints.back();
  EXPECT_THROW(render_reference(medium, view, fewer), InputError);
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

// A Moon so far away (and so large) that its disk covers the same part of
// the sun from every point a path visits, d sun radii from the sun's centre
// with radius rho sun radii: every sunlit term then takes the same share.
TraceOptions far_moon(const glm::dvec3& sun, double sun_radius, double d, double rho) {
  glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(0, 1, 0)));
  double distance = 1e15;
  TraceOptions o;
  o.moon_centre_atmo =
      distance * (std::cos(d * sun_radius) * sun + std::sin(d * sun_radius) * side);
  o.moon_radius = distance * std::sin(rho * sun_radius);
  return o;
}

TEST(PathTracerTest, EverySunlitTermTakesTheMoonsShareOfTheSun) {
  // The same paths (the Moon draws no numbers) with and without the Moon:
  // the air's and the ground's sunlight, at every order, scale by the
  // share, so the radiances' ratio is the share in each channel (R, G, B
  // at the limb darkening's own 680, 550, 440 nm).
  AtmosphereModel model = earth_model();
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  const ColumnTable table(medium);
  glm::dvec3 sun = glm::normalize(glm::dvec3(0.5, 0.0, std::sqrt(0.75)));
  glm::dvec3 origin(0, 0, 6360e3 + 10e3);
  TraceOptions eclipsed = far_moon(sun, model.sun_angular_radius, 0.6, 1.05);
  glm::dvec3 share = shared::occluded_sun_fraction(
      sun, model.sun_angular_radius, eclipsed.moon_centre_atmo - origin, eclipsed.moon_radius);
  ASSERT_GT(share.g, 0.05);
  ASSERT_LT(share.g, 0.5);
  for (glm::dvec3 dir : {glm::dvec3(0.0, 0.7071, 0.7071), glm::dvec3(0.0, 0.6, -0.8)}) {
    for (int channel = 0; channel < 3; ++channel) {
      RadianceEstimate clear =
          estimate_radiance(table, size_t(channel), origin, dir, sun, TraceOptions(), 200, 7);
      RadianceEstimate dim =
          estimate_radiance(table, size_t(channel), origin, dir, sun, eclipsed, 200, 7);
      EXPECT_NEAR(dim.mean / clear.mean, share[channel], 1e-6 * share[channel])
          << "channel " << channel << " looking " << dir.z;
    }
  }
}

TEST(PathTracerTest, TheMoonHidesTheSunsDiskAndTheUmbraIsDark) {
  // Looking at the sun from inside the umbra: no disk, and with no sky
  // outside the shadow (a Moon that covers the sun from everywhere) no
  // light at all; without the Moon, the disk.
  AtmosphereModel model = earth_model();
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  const ColumnTable table(medium);
  glm::dvec3 sun(0, 0, 1), origin(0, 0, 6360e3 + 2.0);
  TraceOptions total = far_moon(sun, model.sun_angular_radius, 0.0, 1.05);
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_EQ(estimate_radiance(table, size_t(channel), origin, sun, sun, total, 50, 3).mean, 0.0);
    EXPECT_GT(
        estimate_radiance(table, size_t(channel), origin, sun, sun, TraceOptions(), 50, 3).mean,
        medium.channels[size_t(channel)].solar_irradiance);
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
