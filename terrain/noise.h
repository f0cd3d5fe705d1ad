#pragma once
// Gradient noise in three dimensions (Perlin 2002, "Improving Noise": the
// quintic fade and the 12 edge gradients), in double so that a position a
// few thousand kilometres from the body's centre still resolves
// centimetre features.
#include <glm/glm.hpp>

#include <cstdint>

namespace planet {

// Noise in about [-1, 1], zero at integer lattice points; `seed` picks
// one of 2^32 independent fields.
double gradient_noise(const glm::dvec3& p, uint32_t seed);

// A bound on |d noise / dp| and on its second derivative along any line,
// used for the height ranges of tiles (checked by sampling in the tests:
// the largest found are 2.6 and about 12).
constexpr double kNoiseMaxSlope = 3.2;
constexpr double kNoiseMaxCurvature = 16.0;

}  // namespace planet
