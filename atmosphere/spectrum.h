#pragma once
// From a sampled spectrum to linear sRGB (CIE 1931 2-degree observer).
//
// The spectrum is taken as piecewise linear between its samples (zero
// outside them), so sample i carries the weight
//   W_i = integral of hat_i(lambda) * cmf(lambda) d lambda
// for each colour matching function x, y, z, with hat_i the linear
// interpolation basis; the integrals run over the 5 nm CIE table.
// XYZ -> linear sRGB is the IEC 61966-2-1 matrix.
//
// Normalisation, so that RGB and spectral renders can be compared: the
// result is scaled per sRGB component so that a spectrally flat radiance of
// L (per nm) gives (L, L, L). An RGB render stores, in each component, the
// radiance per nm at that component's wavelength (680/550/440 nm for Earth),
// so that a flat spectrum gives (L, L, L) there too. Both are then radiance
// per nm in the units of the body's solar irradiance; where they differ for
// the same atmosphere, the difference is the error of rendering at three
// wavelengths (the "spectral error" of the RGB techniques).
#include <glm/glm.hpp>

#include <vector>

namespace planet {

// The sRGB weight of each sample: sum_i L_i * weights[i] is the linear sRGB
// of the spectrum L sampled at `wavelengths_nm` (increasing).
std::vector<glm::dvec3> srgb_weights(const std::vector<double>& wavelengths_nm);

// CIE 1931 2-degree colour matching functions at a wavelength, linearly
// interpolated in the 5 nm table (zero outside 360-830 nm).
glm::dvec3 cie1931_xyz(double wavelength_nm);

// IEC 61966-2-1: CIE XYZ to linear sRGB (D65 white).
glm::dvec3 linear_srgb_from_xyz(const glm::dvec3& xyz);

}  // namespace planet
