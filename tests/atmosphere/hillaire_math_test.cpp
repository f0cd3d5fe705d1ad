// The Legendre series of Cornette-Shanks and the forward gain
// (atmosphere/shaders/hillaire_functions.glsl, compiled as C++), against
// direct integration and against light scattered at random.
#include "atmosphere/math/hillaire_math.h"
#include "atmosphere/reference/sampling.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

double legendre(int l, double nu) {
  double before = 1.0, p = nu;
  if (l == 0) return before;
  for (int k = 2; k <= l; ++k) {
    double next = ((2 * k - 1) * nu * p - (k - 1) * before) / k;
    before = p;
    p = next;
  }
  return p;
}

// g_l = 2 pi int p(nu) P_l(nu) dnu, by the midpoint rule.
double legendre_coefficient(double g, int l) {
  const int n = 400000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double nu = -1.0 + 2.0 * (i + 0.5) / n;
    sum += shared::cornette_shanks_phase(g, nu) * legendre(l, nu);
  }
  return 2.0 * shared::kPi * sum * 2.0 / n;
}

TEST(HillaireMathTest, CornetteShanksLegendreCoefficientsMatchTheIntegral) {
  for (double g : {0.0, 0.5, 0.75, 0.8, -0.3}) {
    for (int l = 0; l <= 8; ++l) {
      EXPECT_NEAR(shared::cornette_shanks_legendre(g, l), legendre_coefficient(g, l), 2e-6)
          << "g " << g << " l " << l;
    }
  }
}

// The basis of the multiple-scattering table's terms: orthonormal in the
// mean over the sphere, and, for each degree l, summing over its parts to
// (2l + 1) P_l averaged over a direction and its mirror image across the
// sun's vertical plane (the addition theorem without the sin(m phi) terms,
// which a field even across that plane does not have). scattered_field
// relies on both.
TEST(HillaireMathTest, FieldBasisIsOrthonormalAndAddsUpToLegendre) {
  const int rows = 180, columns = 360;
  std::vector<double> gram(size_t(hillaire::kFieldParts * hillaire::kFieldParts), 0.0);
  for (int j = 0; j < rows; ++j) {
    double z = 1.0 - 2.0 * (j + 0.5) / rows;  // uniform in z: equal areas
    double s = std::sqrt(1.0 - z * z);
    for (int i = 0; i < columns; ++i) {
      double phi = 2.0 * shared::kPi * (i + 0.5) / columns;
      double x = s * std::cos(phi), y = s * std::sin(phi);
      for (int a = 0; a < hillaire::kFieldParts; ++a) {
        for (int b = 0; b < hillaire::kFieldParts; ++b) {
          gram[size_t(a * hillaire::kFieldParts + b)] +=
              hillaire::field_basis(a, x, y, z) * hillaire::field_basis(b, x, y, z);
        }
      }
    }
  }
  for (int a = 0; a < hillaire::kFieldParts; ++a) {
    for (int b = 0; b < hillaire::kFieldParts; ++b) {
      EXPECT_NEAR(gram[size_t(a * hillaire::kFieldParts + b)] / (rows * columns),
                  a == b ? 1.0 : 0.0, 1e-3)
          << "parts " << a << ", " << b;
    }
  }
  reference::Rng rng(7);
  auto random_direction = [&] {
    double z = 2.0 * rng.uniform() - 1.0, phi = 2.0 * shared::kPi * rng.uniform();
    double s = std::sqrt(1.0 - z * z);
    return glm::dvec3(s * std::cos(phi), s * std::sin(phi), z);
  };
  for (int trial = 0; trial < 100; ++trial) {
    glm::dvec3 w = random_direction(), d = random_direction();
    glm::dvec3 mirror(w.x, -w.y, w.z);
    for (int l = 0; l <= hillaire::kFieldDegree; ++l) {
      double sum = 0.0;
      for (int part = l * (l + 1) / 2; part < (l + 1) * (l + 2) / 2; ++part) {
        sum +=
            hillaire::field_basis(part, w.x, w.y, w.z) * hillaire::field_basis(part, d.x, d.y, d.z);
      }
      double expected =
          (2 * l + 1) * 0.5 * (legendre(l, glm::dot(w, d)) + legendre(l, glm::dot(mirror, d)));
      EXPECT_NEAR(sum, expected, 1e-12) << "degree " << l;
    }
  }
}

// The angular distribution, over the cosine nu to the sun, of sunlight
// scattered once (true phase) and then a Poisson number of times more over
// Mie scattering depth tau, all within a homogeneous medium that keeps
// every photon: by Funk-Hecke, term l of it is (2l + 1) / (4 pi) g_l
// exp((g_l - 1) tau). The forward gain is its part past the table's
// degree L beyond what single scattering gives, so the whole distribution
// is
//   exp(-tau) p + exp(-tau) forward_gain + the terms l <= L of the rest.
double spread_distribution(double g, double nu, double tau) {
  double low = 0.0;
  for (int l = 0; l <= hillaire::kFieldDegree; ++l) {
    double g_l = shared::cornette_shanks_legendre(g, l);
    low += (2 * l + 1) / (4.0 * shared::kPi) * g_l *
           (std::exp((g_l - 1.0) * tau) - std::exp(-tau)) * legendre(l, nu);
  }
  return std::exp(-tau) * shared::cornette_shanks_phase(g, nu) +
         hillaire::forward_gain_times_extinction(g, 0.0, nu, tau) + low;
}

TEST(HillaireMathTest, ForwardGainMatchesLightScatteredAtRandom) {
  using reference::Rng;
  for (double g : {0.75, 0.8}) {
    for (double tau : {0.5, 2.0}) {
      // Bins of equal width in sin(theta / 2), the LUT's mapping.
      const int bins = 16;
      const int photons = 400000;
      std::vector<double> counts(bins, 0.0);
      Rng rng(uint64_t(1000 * g + 10 * tau));
      const glm::dvec3 sun(0, 0, 1);
      for (int i = 0; i < photons; ++i) {
        glm::dvec3 d = reference::direction_about(sun, reference::sample_cornette_shanks_mu(g, rng),
                                                  2.0 * shared::kPi * rng.uniform());
        for (double t = -std::log(1.0 - rng.uniform()); t < tau;
             t -= std::log(1.0 - rng.uniform())) {
          d = reference::direction_about(d, reference::sample_cornette_shanks_mu(g, rng),
                                         2.0 * shared::kPi * rng.uniform());
        }
        double s = std::sqrt(std::max(0.5 * (1.0 - glm::dot(d, sun)), 0.0));
        counts[size_t(std::min(int(s * bins), bins - 1))] += 1.0;
      }
      for (int b = 0; b < bins; ++b) {
        // The bin's probability: 2 pi int f dnu over nu = 1 - 2 s^2.
        const int n = 400;
        double expected = 0.0;
        for (int k = 0; k < n; ++k) {
          double s = (b + (k + 0.5) / n) / bins;
          double dnu = 4.0 * s / (bins * n);
          expected += 2.0 * shared::kPi * spread_distribution(g, 1.0 - 2.0 * s * s, tau) * dnu;
        }
        double measured = counts[size_t(b)] / photons;
        double sigma = std::sqrt(expected * (1.0 - expected) / photons);
        EXPECT_NEAR(measured, expected, 4.0 * sigma + 1e-5)
            << "g " << g << " tau " << tau << " bin " << b;
      }
    }
  }
}

TEST(HillaireMathTest, ForwardGainMovesLightWithoutMakingIt) {
  for (double g : {0.75, 0.8}) {
    EXPECT_EQ(hillaire::forward_gain_times_extinction(g, 0.0, 0.3, 0.0), 0.0);
    for (double tau : {0.1, 1.0, 10.0}) {
      // No light made or lost: the gain integrates to zero over the sphere.
      const int n = 200000;
      double total = 0.0, magnitude = 0.0;
      for (int i = 0; i < n; ++i) {
        double nu = -1.0 + 2.0 * (i + 0.5) / n;
        double gain = hillaire::forward_gain_times_extinction(g, 0.0, nu, tau);
        total += gain;
        magnitude += std::abs(gain);
      }
      EXPECT_LT(std::abs(total), 1e-6 * magnitude) << "g " << g << " tau " << tau;
      // Light is moved toward the sun.
      EXPECT_GT(hillaire::forward_gain_times_extinction(g, 0.0, 1.0, tau), 0.0);
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
