#pragma once
// Random numbers and the sampling routines of the path tracer. Every
// distribution here is sampled exactly (pdf equal to the function sampled),
// so that a path's weight never changes at a scattering event; the
// chi-square tests in tests/atmosphere check each one against its pdf.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace planet::reference {

// SplitMix64 (Steele, Lea and Flood 2014): a counter-based generator whose
// whole state is one 64-bit word, so a stream is fixed by its seed alone.
inline uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(mix64(seed)) {}
  // The stream of one (scene, pixel, sample): the same numbers whatever
  // thread draws them, so renders are identical at any thread count.
  static Rng for_sample(uint64_t scene, uint64_t pixel, uint64_t sample) {
    return Rng(mix64(scene ^ mix64(pixel * 0x9e3779b97f4a7c15ull + mix64(sample + 1))));
  }
  uint64_t next() {
    state_ += 0x9e3779b97f4a7c15ull;
    return mix64(state_);
  }
  // Uniform in [0, 1), 53 bits.
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }

 private:
  uint64_t state_;
};

constexpr double kPi = 3.14159265358979323846;

// A unit vector at angle acos(mu) from `axis`, at azimuth phi about it.
inline glm::dvec3 direction_about(const glm::dvec3& axis, double mu, double phi) {
  // Duff et al. 2017, "Building an orthonormal basis, revisited".
  double sign = std::copysign(1.0, axis.z);
  double a = -1.0 / (sign + axis.z);
  double b = axis.x * axis.y * a;
  glm::dvec3 t(1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
  glm::dvec3 s(b, sign + axis.y * axis.y * a, -axis.y);
  double sin_theta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * s + mu * axis;
}

// Rayleigh phase, pdf over mu proportional to 1 + mu^2: the CDF
// (mu^3 + 3 mu + 4) / 8 = u inverts by Cardano's formula for the depressed
// cubic mu^3 + 3 mu - 2 z = 0 with z = 4 u - 2.
inline double sample_rayleigh_mu(double u) {
  double z = 4.0 * u - 2.0;
  double s = std::sqrt(z * z + 1.0);
  return std::cbrt(z + s) + std::cbrt(z - s);
}

// Henyey-Greenstein, inverse CDF (Henyey and Greenstein 1941; pbrt-v4
// SampleHenyeyGreenstein). mu is the cosine between the incoming and the
// continued direction, so g > 0 scatters forward.
inline double sample_henyey_greenstein_mu(double g, double u) {
  if (std::abs(g) < 1e-3) return 1.0 - 2.0 * u;
  double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
  return std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
}

// Cornette-Shanks by rejection from Henyey-Greenstein: their ratio is
// 3 (1 + mu^2) / (2 (2 + g^2)), at most 3 / (2 + g^2), so accepting a
// Henyey-Greenstein sample with probability (1 + mu^2) / 2 leaves exactly
// the Cornette-Shanks distribution (acceptance (2 + g^2) / 3 on average).
inline double sample_cornette_shanks_mu(double g, Rng& rng) {
  for (;;) {
    double mu = sample_henyey_greenstein_mu(g, rng.uniform());
    if (2.0 * rng.uniform() < 1.0 + mu * mu) return mu;
  }
}

// A direction uniform in the cone of half-angle alpha about `axis`
// (the sun disk); pdf 1 / (2 pi (1 - cos alpha)).
inline glm::dvec3 sample_cone(const glm::dvec3& axis, double cos_alpha, Rng& rng) {
  double mu = 1.0 - rng.uniform() * (1.0 - cos_alpha);
  return direction_about(axis, mu, 2.0 * kPi * rng.uniform());
}

// Lambert: cosine-weighted about the normal, pdf mu / pi.
inline glm::dvec3 sample_cosine(const glm::dvec3& normal, Rng& rng) {
  double mu = std::sqrt(rng.uniform());
  return direction_about(normal, mu, 2.0 * kPi * rng.uniform());
}

}  // namespace planet::reference
