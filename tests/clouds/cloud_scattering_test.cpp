// The clouds' multiple scattering (cloud_octaves, cloud_scattering.glsl)
// against a plane-parallel deck's albedo: the octaves integrated over a
// deck of the layer's optical depth, in the shared math, reflect what the
// delta-Eddington approximation says such a deck reflects.
#include "clouds/cloud_model.h"
#include "clouds/math/cloud_math.h"
#include "sim/body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kPi = std::numbers::pi;
constexpr double kDiameterUm = 20.0;  // Earth's droplets

// The phase function's mean cosine, by quadrature over the angle.
double mean_cosine() {
  const int n = 200000;
  double g = 0;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * kPi / n;
    g += 2.0 * kPi * shared::cloud_phase(kDiameterUm, std::cos(theta)) * std::cos(theta) *
         std::sin(theta) * kPi / n;
  }
  return g;
}

// Joseph, Wiscombe and Weinman 1976, the delta-Eddington reflectance of a
// conservatively scattering deck of optical depth tau lit at cosine mu0:
// ((1 - g) tau + (2/3 - mu0)(1 - exp(-tau' / mu0))) / (4/3 + (1 - g) tau),
// with tau' = (1 - g^2) tau the delta-scaled depth ((1 - g) tau is
// unchanged by the scaling).
double eddington_albedo(double tau, double mu0, double g) {
  const double t = (1.0 - g) * tau;
  return (t + (2.0 / 3.0 - mu0) * (1.0 - std::exp(-(1.0 - g * g) * tau / mu0))) /
         (4.0 / 3.0 + t);
}

// The octaves' albedo of a deck of optical depth tau lit at cosine mu0:
// the radiance each view direction (cosine mu from the zenith, azimuth
// phi from the sun's) takes from the deck, the source cloud_octaves at
// optical depth t (t / mu0 toward the sun) attenuated by exp(-t / mu) on
// its way out, integrated over the upper hemisphere against mu and over
// the incident flux mu0 (per unit of the sun's irradiance).
double octave_albedo(double tau, double mu0, int octaves) {
  const int n_mu = 48, n_phi = 48, n_t = 400;
  const double sin0 = std::sqrt(1.0 - mu0 * mu0);
  double flux = 0;
  for (int i = 0; i < n_mu; ++i) {
    const double mu = (i + 0.5) / n_mu;
    for (int j = 0; j < n_phi; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / n_phi;
      // The scattering angle between the sun's light (down, toward -sun)
      // and the way out toward the viewer (up at mu).
      const double nu = -(mu * mu0 + std::sqrt(1.0 - mu * mu) * sin0 * std::cos(phi));
      const double phase = shared::cloud_phase(kDiameterUm, nu);
      double radiance = 0;
      for (int k = 0; k < n_t; ++k) {
        const double t = (k + 0.5) * tau / n_t;
        radiance += std::exp(-t / mu) * shared::cloud_octaves(phase, t / mu0, mu0, octaves) *
                    (tau / n_t) / mu;
      }
      flux += radiance * mu * (1.0 / n_mu) * (2.0 * kPi / n_phi);
    }
  }
  return flux / mu0;
}

// Earth's layer's optical depth through a column at the place of the
// shipped flights' overcast (-30, -40) and around it, from the density
// field itself.
double overcast_optical_depth() {
  std::optional<CloudModel> model = load_clouds(load_body(find_body_file("earth")));
  const shared::CloudLayer layer = to_shared(*model, 6360e3);
  double sum = 0;
  int columns = 0;
  for (double lat_deg = -31.0; lat_deg <= -29.0; lat_deg += 0.5) {
    for (double lon_deg = -41.0; lon_deg <= -39.0; lon_deg += 0.5) {
      const double lat = lat_deg * kPi / 180.0, lon = lon_deg * kPi / 180.0;
      const glm::dvec3 up(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                          std::sin(lat));
      const double dz = 5.0;
      for (double r = layer.bottom_radius; r < layer.top_radius; r += dz) {
        sum += shared::cloud_extinction(layer, (r + 0.5 * dz) * up) * dz;
      }
      ++columns;
    }
  }
  return sum / columns;
}

TEST(CloudScatteringTest, OctavesReflectAsAnEddingtonDeckDoes) {
  const double g = mean_cosine();
  const double tau_overcast = overcast_optical_depth();
  std::printf("phase mean cosine %.4f; Earth's overcast at (-30, -40): optical depth %.1f\n", g,
              tau_overcast);
  EXPECT_GT(tau_overcast, 10.0);
  EXPECT_LT(tau_overcast, 40.0);
  for (double tau : {5.0, 10.0, 20.0, 40.0}) {
    for (double mu0 : {0.3, 0.574, 0.9}) {
      const double octaves = octave_albedo(tau, mu0, 6), eddington = eddington_albedo(tau, mu0, g);
      std::printf("tau %4.0f mu0 %.3f: octaves %.3f, delta-Eddington %.3f, ratio %.2f\n", tau,
                  mu0, octaves, eddington, octaves / eddington);
      // At the overcast's optical depth, within 15 % (measured: 0.90 to
      // 1.02; docs/clouds.md#brightness); with all of the irradiance in
      // every octave and b = 1/2 the octaves gave 0.28 at mu0 0.574, 0.55
      // of the 0.51 due. Thicker decks come out darker than they are (the
      // octaves' albedo does not grow with depth): 0.50 to 0.75 at 40.
      if (tau == 10.0) {
        EXPECT_GT(octaves / eddington, 0.85) << mu0;
        EXPECT_LT(octaves / eddington, 1.15) << mu0;
      }
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
