#pragma once
// Lorenz-Mie scattering by a homogeneous sphere, the series as Bohren and
// Huffman 1983 (chapter 4 and appendix A) sum it: the reference against
// which the clouds' approximate phase function is measured.
#include <complex>
#include <vector>

namespace planet {

struct MieSphere {
  double q_ext = 0;  // extinction efficiency (cross-section over pi a^2)
  double q_sca = 0;  // scattering efficiency
  double g = 0;      // asymmetry parameter, mean cosine of the scattering angle
  // Per cosine of `mu` asked for: (|S1|^2 + |S2|^2) / 2, the unpolarised
  // scattered intensity (Bohren and Huffman eq. 4.74 with S11).
  std::vector<double> s11;
};

// Size parameter x = 2 pi a / lambda, relative refractive index m (its
// imaginary part >= 0 absorbs), cosines mu of the scattering angles.
MieSphere mie_sphere(double x, std::complex<double> m, const std::vector<double>& mu);

// The phase function (per steradian, integrating to 1) at the cosines mu of
// spheres of diameters spread evenly over [d (1 - spread), d (1 + spread)]
// (n sizes), weighted by their scattering cross-sections: a narrow spread
// washes out the single size's ripples. Diameter and wavelength in the same
// unit.
std::vector<double> mie_phase_table(double diameter, double spread, int n, double wavelength,
                                    std::complex<double> m, const std::vector<double>& mu);

}  // namespace planet
