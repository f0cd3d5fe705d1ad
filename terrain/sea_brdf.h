#pragma once
// The open sea's BRDF (terrain/shaders/sea_brdf.glsl) as C++ in double,
// compiled once in sea_brdf.cpp: the side against which the tests hold the
// GPU's glint.
#include <glm/glm.hpp>

namespace planet::sea {

using Real = double;
using Real3 = glm::dvec3;

Real sea_fresnel(Real cos_i);
Real cox_munk_slope_variance(Real wind_m_s);
Real cox_munk_slope_pdf(Real tan2_beta, Real sigma2);
Real sea_glint(Real3 n, Real3 view, Real3 sun, Real sigma2);

}  // namespace planet::sea
