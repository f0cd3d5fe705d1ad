#pragma once
// O'Neil 2005's scale function and single scattering
// (atmosphere/shaders/oneil_functions.glsl) as C++ in double, compiled once
// in oneil_math.cpp; and the scale function fitted to one exponential
// component of a body's atmosphere, with its measured error, which the
// technique computes when a body loads and `planet probe oneil-fit` prints.
#include "atmosphere/math/shared_math.h"

#include <string>

namespace planet::oneil {

using shared::Atmosphere;
using shared::Real;
using shared::Real2;
using shared::Real3;

#include "atmosphere/shaders/oneil_definitions.glsl"

// oneil_functions.glsl
Real oneil_chapter_scale(Real mu);
Real oneil_shell_path_ratio(Real r, Real mu, Real depth);
Real oneil_polynomial(const OneilScale& s, Real x, Real y);
Real oneil_horizon_variable(Real r, Real depth, Real mu);
Real oneil_height_variable(Real scale_height, Real thickness, Real depth);
Real oneil_column_up(const Atmosphere& atmosphere, const OneilScale& s, Real r, Real mu);
Real oneil_column(const Atmosphere& atmosphere, const OneilScale& s, Real r, Real mu);
Real2 oneil_columns(const Atmosphere& atmosphere, const OneilScale& rayleigh, const OneilScale& mie,
                    const Real3& p, const Real3& d);
Real3 oneil_extinction(const Atmosphere& atmosphere, const Real2& columns);
Real2 oneil_path_columns(const Atmosphere& atmosphere, const OneilScale& rayleigh,
                         const OneilScale& mie, const Real3& o, const Real3& d, bool hits_ground,
                         Real t_a, Real t_b);
void oneil_single_scattering(const Atmosphere& atmosphere, const OneilScale& rayleigh,
                             const OneilScale& mie, const Real3& o, const Real3& d,
                             bool hits_ground, Real t_a, Real t_b, const Real3& sun_dir,
                             int samples, Real3& rayleigh_light, Real3& mie_light,
                             Real3& transmittance);

// The column of density exp(-h / H) from radius r along zenith cosine mu to
// the top, for a ray that misses the ground, by Simpson's rule (the fit's
// truth: within 2e-5 of the closed form on Earth, see its test).
Real exact_column(const Atmosphere& atmosphere, Real scale_height, Real r, Real mu);

// How far a scale function's column is from exact_column over its domain:
// heights 0 to the top, and every zenith cosine whose ray misses the ground
// (a grid of 101 heights by 241 cosines, denser toward the horizon).
struct ScaleError {
  double worst_relative = 0;
  double worst_h = 0, worst_mu = 0;  // where it is
  // The worst absolute error as a fraction of the vertical column from the
  // ground: what the transmittance sees where the column itself is small.
  double worst_of_vertical = 0;
};
ScaleError measure_scale_error(const Atmosphere& atmosphere, const OneilScale& scale);

// The chapter's fixed polynomial, for a component of scale height H.
OneilScale chapter_scale(Real scale_height);
// The fitted form (oneil_functions.glsl) by least squares on the logarithm
// of the column's ratio to its closed-form part, then reweighted toward the
// worst residuals so that the fit approaches the smallest worst error.
OneilScale fit_scale(const Atmosphere& atmosphere, Real scale_height);

// H of a profile that is one exponential layer exp(-h / H), as the scale
// function needs; InputError naming the component otherwise.
Real exponential_scale_height(const shared::DensityProfile& profile, const std::string& component);

// A body's two scale functions, fitted, with their errors.
struct BodyScales {
  OneilScale rayleigh, mie;
  ScaleError rayleigh_error, mie_error;
};
BodyScales fit_body_scales(const AtmosphereModel& model);

}  // namespace planet::oneil
