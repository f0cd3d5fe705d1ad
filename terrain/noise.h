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

namespace planet {

// Two-dimensional gradient noise on the integer lattice that vanishes
// along chosen lattice lines, for detail that must average to zero over
// the cells those lines bound (terrain/grid_detail.cpp). Lattice points
// (a, b) with a = 0 modulo `m` (axis 0) or b = 0 modulo `m` (axis 1),
// and those with a = b = `sample` modulo `m`, have no gradient; the rest
// one of eight unit gradients (the axes and the diagonals). The noise is
// then zero all along the chosen lines, its slope across them too, and
// both at the `sample` points. Columns wrap every `period` points.
struct EdgeNoise {
  double value = 0, slope = 0;  // the noise and its derivative along its axis
};
EdgeNoise edge_noise(double x, double y, int axis, int64_t m, int64_t sample, int64_t period,
                     uint32_t seed);
// Both at once, F (axis 0, seed_f) and G (axis 1, seed_g), sharing the
// lattice cell and its weights. `m` must be a power of two.
void edge_noise_pair(double x, double y, int64_t m, int64_t sample, int64_t period, uint32_t seed_f,
                     uint32_t seed_g, EdgeNoise& f, EdgeNoise& g);

// Bounds on the edge noise's value, its first derivatives and its second
// derivatives along the axes; and on the divergence F_x + G_y of two of
// them (axis 0 and axis 1, other seeds) and its slope along either axis.
// Checked by sampling in the tests, where the largest found are 0.685,
// 1.95, 8.2, 2.67 and 10.9: each bound is about 10 % over.
constexpr double kEdgeNoiseMax = 0.75;
constexpr double kEdgeNoiseMaxSlope = 2.15;
constexpr double kEdgeNoiseMaxCurvature = 9.0;
constexpr double kEdgeDivergenceMax = 2.95;
constexpr double kEdgeDivergenceMaxSlope = 12.0;

}  // namespace planet
