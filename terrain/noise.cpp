#include "terrain/noise.h"

#include <cmath>

namespace planet {

namespace {

// A 32-bit integer hash (Wang-style mix of the lattice coordinates and the
// seed): the permutation table of Perlin's paper without a table.
uint32_t hash(int64_t x, int64_t y, int64_t z, uint32_t seed) {
  uint64_t h = uint64_t(x) * 0x9E3779B97F4A7C15ull ^ uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^
               uint64_t(z) * 0x165667B19E3779F9ull ^ uint64_t(seed) * 0x27D4EB2F165667C5ull;
  h ^= h >> 31;
  h *= 0x7FB5D329728EA185ull;
  h ^= h >> 27;
  h *= 0x81DADEF4BC2DD44Dull;
  h ^= h >> 33;
  return uint32_t(h);
}

// Perlin 2002: the gradient is one of the 12 cube-edge directions.
double grad(uint32_t h, double x, double y, double z) {
  switch (h % 12u) {
    case 0:
      return x + y;
    case 1:
      return -x + y;
    case 2:
      return x - y;
    case 3:
      return -x - y;
    case 4:
      return x + z;
    case 5:
      return -x + z;
    case 6:
      return x - z;
    case 7:
      return -x - z;
    case 8:
      return y + z;
    case 9:
      return -y + z;
    case 10:
      return y - z;
    default:
      return -y - z;
  }
}

// 6t^5 - 15t^4 + 10t^3: C2, so normals taken from the noise are smooth.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double lerp(double a, double b, double t) { return a + t * (b - a); }

}  // namespace

double gradient_noise(const glm::dvec3& p, uint32_t seed) {
  double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
  int64_t X = int64_t(fx), Y = int64_t(fy), Z = int64_t(fz);
  double x = p.x - fx, y = p.y - fy, z = p.z - fz;
  double u = fade(x), v = fade(y), w = fade(z);
  auto g = [&](int dx, int dy, int dz) {
    return grad(hash(X + dx, Y + dy, Z + dz, seed), x - dx, y - dy, z - dz);
  };
  double x00 = lerp(g(0, 0, 0), g(1, 0, 0), u), x10 = lerp(g(0, 1, 0), g(1, 1, 0), u);
  double x01 = lerp(g(0, 0, 1), g(1, 0, 1), u), x11 = lerp(g(0, 1, 1), g(1, 1, 1), u);
  return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

namespace {

uint32_t edge_hash(int64_t x, int64_t y, uint32_t seed) {
  uint64_t h = uint64_t(x) * 0x9E3779B97F4A7C15ull ^ uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^
               uint64_t(seed) * 0x165667B19E3779F9ull;
  h ^= h >> 31;
  h *= 0x7FB5D329728EA185ull;
  h ^= h >> 27;
  h *= 0x81DADEF4BC2DD44Dull;
  h ^= h >> 33;
  return uint32_t(h);
}

constexpr double kDiagonal = 0.70710678118654752;
constexpr double kEdgeGradients[8][2] = {{1, 0},
                                         {-1, 0},
                                         {0, 1},
                                         {0, -1},
                                         {kDiagonal, kDiagonal},
                                         {-kDiagonal, kDiagonal},
                                         {kDiagonal, -kDiagonal},
                                         {-kDiagonal, -kDiagonal}};

int64_t modulo(int64_t a, int64_t n) { return ((a % n) + n) % n; }
double fade_slope(double t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); }

}  // namespace

void edge_noise_pair(double x, double y, int64_t m, int64_t sample, int64_t period, uint32_t seed_f,
                     uint32_t seed_g, EdgeNoise& f, EdgeNoise& g) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto X = int64_t(fx), Y = int64_t(fy);
  const double tx = x - fx, ty = y - fy;
  const double wx[2] = {1.0 - fade(tx), fade(tx)}, wy[2] = {1.0 - fade(ty), fade(ty)};
  const double sx = fade_slope(tx), sy = fade_slope(ty);
  const double dwx[2] = {-sx, sx}, dwy[2] = {-sy, sy};
  // m is a power of two: its remainders are masks (two's complement keeps
  // them right below zero); columns wrap once.
  const int64_t mask = m - 1;
  const int64_t a0 = modulo(X, period);
  const int64_t columns[2] = {a0, a0 + 1 == period ? 0 : a0 + 1};
  f = {};
  g = {};
  for (int cy = 0; cy < 2; ++cy) {
    const int64_t b = Y + cy, bm = b & mask;
    for (int cx = 0; cx < 2; ++cx) {
      const int64_t a = columns[cx], am = a & mask;
      if (am == sample && bm == sample) continue;
      const double dx = tx - cx, dy = ty - cy;
      const double w = wx[cx] * wy[cy];
      if (am != 0) {
        const double* gr = kEdgeGradients[edge_hash(a, b, seed_f) & 7u];
        const double dot = gr[0] * dx + gr[1] * dy;
        f.value += w * dot;
        f.slope += dwx[cx] * wy[cy] * dot + w * gr[0];
      }
      if (bm != 0) {
        const double* gr = kEdgeGradients[edge_hash(a, b, seed_g) & 7u];
        const double dot = gr[0] * dx + gr[1] * dy;
        g.value += w * dot;
        g.slope += wx[cx] * dwy[cy] * dot + w * gr[1];
      }
    }
  }
}

EdgeNoise edge_noise(double x, double y, int axis, int64_t m, int64_t sample, int64_t period,
                     uint32_t seed) {
  EdgeNoise f, g;
  edge_noise_pair(x, y, m, sample, period, seed, seed, f, g);
  return axis == 0 ? f : g;
}

}  // namespace planet
