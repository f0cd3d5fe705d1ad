#pragma once
// The density columns of a spherical atmosphere: for a straight ray from
// radius r at zenith cosine mu to the top of the atmosphere, the integral of
// each component's density profile along it (in metres of density 1). A
// channel's optical depth is then its three coefficients times the three
// columns, so one table serves every channel.
//
// The table is indexed like Bruneton and Neyret's transmittance texture
// (2008; "precomputed_atmospheric_scattering", 2017): x_r = rho / H and
// x_mu = (d - d_min) / (d_max - d_min), which packs texels at the horizon,
// for rays that miss the ground. Each texel is integrated by Gauss-Legendre
// in s = sqrt(r - r_p), r_p the ray's least distance from the centre: the
// integrand is then smooth through the tangent point (no 1 / sqrt there),
// and the layers' kinks are break points of the rule.
//
// With columns, the optical depth between two points of a ray is a
// difference of two lookups, and the sun's transmittance one lookup: the
// path tracer's transmittances are then exact to the table's interpolation
// (the tests bound it) instead of a noisy estimate.
#include "atmosphere/reference/medium.h"

#include <glm/glm.hpp>

#include <vector>

namespace planet {

class ColumnTable {
 public:
  // Texels in x_r and x_mu. At the defaults the interpolation's error in a
  // channel's optical depth is 1e-5 RMS and at most 2e-4 over the shell
  // (tests/atmosphere/path_tracer_test.cpp), on Earth and Mars.
  explicit ColumnTable(const Medium& medium, int r_size = 1024, int mu_size = 1024);

  // Columns (rayleigh, mie, absorber) from radius r (clamped to the shell)
  // along zenith cosine mu to the top; mu is clamped to the horizon, so a
  // ray into the ground gets the grazing ray's columns.
  glm::dvec3 to_top(double r, double mu) const;
  glm::dvec3 to_top(const glm::dvec3& p, const glm::dvec3& dir) const;

  // The same integral by the quadrature alone, no table (for the tests and
  // for building the table).
  glm::dvec3 integrate_to_top(double r, double mu) const;

  const Medium& medium() const { return medium_; }

  // Where (r, mu) falls in the table: texel (i, j) and the weights of its
  // neighbours (i + 1, j + 1).
  struct Cell {
    int i, j;
    double fu, fv;
  };
  Cell locate(double r, double mu) const;
  int r_size() const { return r_size_; }
  int mu_size() const { return mu_size_; }
  // The columns at texel (i, j).
  glm::dvec3 texel(int i, int j) const;

 private:
  const Medium& medium_;
  int r_size_, mu_size_;
  double horizon_;              // sqrt(top^2 - bottom^2): the horizon ray's length from the top
  std::vector<double> breaks_;  // altitudes where a profile has a kink
  double step_ = 0;             // the rule's largest piece, in altitude
  std::vector<glm::dvec3> texels_;
};

// A channel's optical depth from its columns.
inline double optical_depth(const MediumChannel& c, const glm::dvec3& columns) {
  return c.rayleigh_scattering * columns.x + (c.mie_scattering + c.mie_absorption) * columns.y +
         c.absorber_absorption * columns.z;
}

// One channel's optical depth to the top, tabled on the columns' texels:
// log(depth + 1e-7) of its Rayleigh and of its aerosol part, each falling
// exponentially with its own scale height, and the absorber's depth as it
// is (Earth's ozone is a layer, not an exponential; its logarithm does not
// interpolate linearly, nor does that of a sum of exponentials with
// different scale heights: either way the error grows 15x, measured). Two
// exponentials a lookup where the columns take three, in floats: half the
// memory. The tests bound its error with the columns'.
class DepthTable {
 public:
  DepthTable(const ColumnTable& columns, const MediumChannel& channel);

  double to_top(double r, double mu) const;
  double to_top(const glm::dvec3& p, const glm::dvec3& dir) const {
    double r = glm::length(p);
    return to_top(r, glm::dot(p, dir) / r);
  }

  const Medium& medium() const { return columns_.medium(); }
  const MediumChannel& channel() const { return channel_; }

 private:
  const ColumnTable& columns_;
  const MediumChannel& channel_;
  std::vector<glm::vec3> texels_;
};

}  // namespace planet
