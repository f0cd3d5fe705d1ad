#pragma once
// Crater fields: craters placed on a 3D lattice of cells (one at most per
// cell, with a chance, at a drawn place and radius), their simple-crater
// profile and their marks on the ground. The procedural heights lay them
// in octaves of cell sizes; the grid's detail (grid_detail.h) lays the
// ones below its cell size, keeping those that stay within one cell.
#include "terrain/height_source.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace planet::craters {

inline double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// A simple crater, depth D and radius R, as a function of x = d / R: a
// parabolic bowl whose floor lies D below the plain, and a rim 0.3 D high
// that falls back to the plain by x = 2.5 (the simple-crater shape of
// Melosh 1989, ch. 6). Bowl and rim meet through a polynomial smooth
// minimum (Quilez 2013) of width 0.2, which keeps the profile C1 with
// bounded curvature, so that its interpolation error is bounded as h^2.
inline double profile(double x) {
  double bowl = x * x - 0.7;
  double rim = 0.3 * (1.0 - smoothstep(1.0, 2.5, x));
  constexpr double k = 0.2;
  double m = std::clamp(0.5 + 0.5 * (rim - bowl) / k, 0.0, 1.0);
  return rim + (bowl - rim) * m - k * m * (1.0 - m);
}
// Its slope and curvature bounds in units of D / R and D / R^2: the bowl's
// slope 2x up to where the minimum hands over (x ~ 1.2), and its curvature
// 2 plus the blend's (bowl' - rim')^2 / (2 k).
constexpr double kMaxSlope = 3.0;
constexpr double kMaxCurvature = 20.0;
constexpr double kReach = 2.5;  // profile is zero beyond this many radii

// The same crater holding no volume: what its bowl digs out lies on its
// rim and blanket, as an impact moves the ground rather than adds to it.
// profile() holds 0.2229 R^2 D (its integral of x p(x) dx over [0, 2.5]);
// the bowl is deepened by kVolumeShift (1 - smoothstep(0, 1.2, x)), whose
// integral of x (...) is 0.216, so that the two cancel (the terrain test
// integrates it). Its floor lies 1.732 D below the plain and its rim
// 0.287 D above: kZeroVolumeDepth from floor to rim crest. Its slope
// stays under 2.8 and its curvature under 17 (kMaxSlope, kMaxCurvature hold).
constexpr double kVolumeShift = 1.0320911816371614;
constexpr double kZeroVolumeDepth = 2.0195;
inline double zero_volume_profile(double x) {
  return profile(x) - kVolumeShift * (1.0 - smoothstep(0.0, 1.2, x));
}

// Crater radii in cells, and how many craters can overlap at a point (one
// per cell of the 2 x 2 x 2 block that can reach it).
constexpr double kMinRadius = 0.1, kMaxRadius = 0.25;
constexpr double kOverlap = 8.0;

inline uint32_t cell_hash(int64_t x, int64_t y, int64_t z, uint32_t seed) {
  uint64_t h = uint64_t(x) * 0xD6E8FEB86659FD93ull ^ uint64_t(y) * 0xA0761D6478BD642Full ^
               uint64_t(z) * 0xE7037ED1A0B428DBull ^ uint64_t(seed) * 0x8EBC6AF09C88C6E3ull;
  h ^= h >> 32;
  h *= 0x9E3779B97F4A7C15ull;
  h ^= h >> 29;
  return uint32_t(h);
}
inline double unit(uint32_t& state) {
  state = state * 1664525u + 1013904223u;  // Numerical Recipes LCG, enough for placement
  return double(state >> 8) / double(1u << 24);
}

// The crater of cell (x, y, z), if it holds one (chance `density`): its
// centre c drawn within the cell in the order z, y, x, then its radius r
// (each draw its own statement, so that every compiler places the same
// craters), between 0.1 and 0.25 cell; s is the state its cell's further
// draws go on from.
inline bool draw_crater(int64_t x, int64_t y, int64_t z, double density, uint32_t seed, uint32_t& s,
                        glm::dvec3& c, double& r) {
  s = cell_hash(x, y, z, seed);
  if (unit(s) >= density) return false;
  c.z = double(z) + unit(s);
  c.y = double(y) + unit(s);
  c.x = double(x) + unit(s);
  r = kMinRadius + (kMaxRadius - kMinRadius) * unit(s);
  return true;
}

// Calls f(q, c, r, s) for each crater that can reach p: q is p and c the
// crater's centre in cells of a lattice of spacing `cell`, r its radius
// in cells, s the state its cell's draws go on from (draw_crater). A
// crater reaches at most 0.625 cell from its centre, and only the
// neighbour cells on the near side of each axis can touch p.
template <typename F>
void for_each_crater(const glm::dvec3& p, double cell, double density, uint32_t seed, F&& f) {
  const glm::dvec3 q = p / cell;
  const glm::dvec3 floor = glm::floor(q);
  const glm::dvec3 frac = q - floor;
  auto lo = [](double t) { return t < kMaxRadius * kReach ? -1 : 0; };
  auto hi = [](double t) { return t > 1.0 - kMaxRadius * kReach ? 1 : 0; };
  auto cx = int64_t(floor.x), cy = int64_t(floor.y), cz = int64_t(floor.z);
  for (int dz = lo(frac.z); dz <= hi(frac.z); ++dz) {
    for (int dy = lo(frac.y); dy <= hi(frac.y); ++dy) {
      for (int dx = lo(frac.x); dx <= hi(frac.x); ++dx) {
        uint32_t s;
        glm::dvec3 c;
        double r;
        if (!draw_crater(cx + dx, cy + dy, cz + dz, density, seed, s, c, r)) continue;
        f(q, c, r, s);
      }
    }
  }
}

// The same lattice's craters laid whole on the sphere through p (of
// radius |p| / cell cells): those whose drawn centre lies within
// kShellHalfWidth cells of the sphere, moved along the radius onto it
// (where their full profile, and so their volume, holds; a centre off the
// sphere cuts a smaller crater, whose volume is not the profile's). Calls
// f(q, c, r, s) with c on the sphere. Moved by at most kShellHalfWidth
// cells along the radius n, a centre reaches p only from cells within
// 0.625 + kShellHalfWidth |n_axis| of it along each axis: still two at most.
constexpr double kShellHalfWidth = 0.35;
template <typename F>
void for_each_surface_crater(const glm::dvec3& p, double cell, double density, uint32_t seed,
                             F&& f) {
  const glm::dvec3 q = p / cell;
  const double sphere = glm::length(q);
  const glm::dvec3 n = q / sphere;
  const glm::dvec3 floor = glm::floor(q);
  const glm::dvec3 frac = q - floor;
  const double reach = kMaxRadius * kReach;
  auto lo = [&](double t, double na) {
    return t < reach + kShellHalfWidth * std::abs(na) ? -1 : 0;
  };
  auto hi = [&](double t, double na) {
    return t > 1.0 - reach - kShellHalfWidth * std::abs(na) ? 1 : 0;
  };
  auto cx = int64_t(floor.x), cy = int64_t(floor.y), cz = int64_t(floor.z);
  for (int dz = lo(frac.z, n.z); dz <= hi(frac.z, n.z); ++dz) {
    for (int dy = lo(frac.y, n.y); dy <= hi(frac.y, n.y); ++dy) {
      for (int dx = lo(frac.x, n.x); dx <= hi(frac.x, n.x); ++dx) {
        uint32_t s;
        glm::dvec3 c;
        double r;
        if (!draw_crater(cx + dx, cy + dy, cz + dz, density, seed, s, c, r)) continue;
        const double length = glm::length(c);
        if (std::abs(length - sphere) > kShellHalfWidth) continue;
        f(q, c * (sphere / length), r, s);
      }
    }
  }
}

// The marks of one crater (q, c, r, s as for_each_crater gives them, the
// lattice's `cell` in metres) on ground sampled every `spacing` metres.
// Each crater draws two more numbers after its radius: its youth y (most
// craters are old: y = u^3), and the phase of its rays. The floor covers
// the bowl; the rim a ring about 1.0-1.4 radii, bright on all but the
// oldest; the ejecta the blanket to 2.5 radii, on young craters alone,
// streaked by the sum of two cosines of the azimuth about the crater's
// centre (whole numbers of periods, so the streaks close on themselves).
// Marks of craters narrower than 1.5 `spacing` (the rim: 3) fade out;
// overlapping craters keep the strongest of each mark.
inline void add_marks(const glm::dvec3& q, const glm::dvec3& c, double r, uint32_t s, double cell,
                      double spacing, CraterMarks& marks) {
  double youth = unit(s);
  youth = youth * youth * youth;
  double phase = 6.283185307179586 * unit(s);
  glm::dvec3 v = q - c;
  double x = glm::length(v) / r;
  if (x >= kReach) return;
  double metres = r * cell;
  double shows = smoothstep(1.5 * spacing, 3.0 * spacing, metres);
  double rim_shows = smoothstep(3.0 * spacing, 6.0 * spacing, metres);
  marks.floor = std::max(marks.floor, shows * (1.0 - smoothstep(0.5, 0.9, x)));
  double ring = smoothstep(0.85, 1.05, x) * (1.0 - smoothstep(1.15, 1.45, x));
  marks.rim = std::max(marks.rim, rim_shows * (0.3 + 0.7 * youth) * ring);
  if (youth > 0.0 && x > 0.95) {
    // The azimuth in a frame about the centre's direction.
    glm::dvec3 n = glm::normalize(c);
    glm::dvec3 e1 = glm::normalize(
        glm::cross(n, std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
    glm::dvec3 e2 = glm::cross(n, e1);
    double azimuth = std::atan2(glm::dot(v, e2), glm::dot(v, e1));
    double streaks = 0.5 + 0.25 * std::cos(7.0 * azimuth + phase) +
                     0.25 * std::cos(12.0 * azimuth + 2.0 * phase);
    double blanket = smoothstep(0.95, 1.15, x) * (1.0 - smoothstep(1.2, kReach, x));
    marks.ejecta =
        std::max(marks.ejecta, shows * youth * blanket * (0.3 + 0.7 * streaks * streaks));
  }
}

}  // namespace planet::craters
