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

// Stratified dimensions: Sobol's first two dimensions (a (0, 2)-sequence in
// base 2), Owen-scrambled by hashing (Laine and Karras 2011; Burley 2020,
// "Practical hash-based Owen scrambling"), with the sample index shuffled
// per pair so that different pairs are not correlated ("padding", as in
// pbrt-v4's PaddedSobolSampler). The first n points of every pair with n a
// power of two are then stratified in every elementary interval of area 1/n.
inline uint32_t reverse_bits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// A random permutation of the 32-bit fractions in which each bit is
// flipped or not by a hash of the bits above it: Owen's nested uniform
// scramble. The multiplications make each bit depend on the lower ones, so
// they run on the reversed bits.
inline uint32_t owen_scramble(uint32_t x, uint32_t seed) {
  x = reverse_bits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverse_bits(x);
}

// Sobol's second dimension: its generator matrix is Pascal's triangle
// mod 2, whose columns are v, v ^ (v >> 1), ... from the top bit.
inline uint32_t sobol_second(uint32_t index) {
  uint32_t v = 1u << 31, x = 0;
  for (; index != 0; index >>= 1, v ^= v >> 1) {
    if (index & 1u) x ^= v;
  }
  return x;
}

// Point `index` of the pair of dimensions scrambled by `seed`, in (0, 1)^2.
inline glm::dvec2 stratified_pair(uint32_t index, uint64_t seed) {
  uint64_t h = mix64(seed);
  uint32_t i = owen_scramble(index, uint32_t(h));
  uint32_t x = owen_scramble(reverse_bits(i), uint32_t(h >> 32));
  uint32_t y = owen_scramble(sobol_second(i), uint32_t(mix64(h)));
  return {(double(x) + 0.5) * 0x1p-32, (double(y) + 0.5) * 0x1p-32};
}

// The numbers of one path: its first kStratifiedPairs pairs from the
// stratified sequence of its pixel and channel (`seed`), at its index in
// that pixel's paths; everything else from its own random stream.
class PathSampler {
 public:
  static constexpr int kStratifiedPairs = 8;
  PathSampler(uint64_t seed, uint32_t index)
      : seed_(seed), index_(index), rng_(Rng::for_sample(seed, index, 0)) {}
  glm::dvec2 pair() {
    if (pair_ < kStratifiedPairs) return stratified_pair(index_, seed_ + uint64_t(pair_++));
    return {rng_.uniform(), rng_.uniform()};
  }
  Rng& rng() { return rng_; }

 private:
  uint64_t seed_;
  uint32_t index_;
  int pair_ = 0;
  Rng rng_;
};

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
// `first` is the first try's number (a stratified one); the rest are
// drawn from `rng`.
inline double sample_cornette_shanks_mu(double g, double first, Rng& rng) {
  for (double u = first;; u = rng.uniform()) {
    double mu = sample_henyey_greenstein_mu(g, u);
    if (2.0 * rng.uniform() < 1.0 + mu * mu) return mu;
  }
}
inline double sample_cornette_shanks_mu(double g, Rng& rng) {
  return sample_cornette_shanks_mu(g, rng.uniform(), rng);
}

// A direction uniform in the cone of half-angle alpha about `axis`
// (the sun disk); pdf 1 / (2 pi (1 - cos alpha)).
inline glm::dvec3 sample_cone(const glm::dvec3& axis, double cos_alpha, Rng& rng) {
  double mu = 1.0 - rng.uniform() * (1.0 - cos_alpha);
  return direction_about(axis, mu, 2.0 * kPi * rng.uniform());
}

// Lambert: cosine-weighted about the normal, pdf mu / pi, from two
// numbers in [0, 1) (stratified ones in the path tracer).
inline glm::dvec3 sample_cosine(const glm::dvec3& normal, const glm::dvec2& u) {
  return direction_about(normal, std::sqrt(u.x), 2.0 * kPi * u.y);
}
inline glm::dvec3 sample_cosine(const glm::dvec3& normal, Rng& rng) {
  double u = rng.uniform();
  return sample_cosine(normal, glm::dvec2(u, rng.uniform()));
}

}  // namespace planet::reference
