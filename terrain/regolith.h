#pragma once
// How a body's regolith reflects sunlight (terrain/shaders/regolith.glsl,
// compiled here in double): the law of the airless bodies' ground, and of
// Mars's, in place of Lambert's, with what the CPU checks of it need.
#include <string>

namespace planet {

// Hapke's parameters, as a body's file gives them under terrain.regolith.
struct Regolith {
  double w = 0.2;          // single-scattering albedo
  double xi = -0.3;        // the grains' Henyey-Greenstein asymmetry (negative: backward)
  double b0 = 1.0;         // the opposition surge's amplitude
  double h = 0.05;         // its angular width
  double theta_bar = 0.0;  // mean slope of the roughness below a pixel, radians
  std::string source;      // where the values come from
};

// Hapke's bidirectional reflectance r (radiance over the irradiance on a
// plane facing the sun) for the incidence and emission cosines and the
// phase angle's cosine: the shader's very function.
double regolith_reflectance(const Regolith& regolith, double mu0, double mu, double cos_g);

// The normal albedo: the ground's radiance factor (pi r) lit and seen
// straight down, the surge included. A body's palette gives each pixel's
// normal albedo A (the Moon's maria 0.07, its highlands 0.16), so the
// ground there reflects A / this times Hapke's r.
double regolith_normal_albedo(const Regolith& regolith);

// The integral of r over the disk of a sphere of unit radius seen at phase
// angle `phase` (radians): the sphere's brightness, in units where at phase
// 0 it is the geometric albedo.
double regolith_disk_brightness(const Regolith& regolith, double phase);

}  // namespace planet
