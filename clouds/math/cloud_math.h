#pragma once
// The shared cloud math (clouds/shaders/*.glsl, see cloud_definitions.glsl)
// as C++ in double, compiled once in cloud_math.cpp the way
// atmosphere/math/shared_math.cpp compiles the atmosphere's: the path
// tracer and the tests run the GPU's formulas. The files' functions in
// their order; a signature that differs from its GLSL fails to link.
#include "atmosphere/math/definitions.h"

namespace planet::shared {

#include "clouds/shaders/cloud_definitions.glsl"

// cloud_noise.glsl
glm::uint cloud_hash(glm::uvec3 v);
Real cloud_lattice_value(glm::ivec3 cell, glm::uint seed);
Real cloud_value_noise(Real3 p, glm::uint seed);
Real cloud_fbm(Real3 p, glm::uint seed, int octaves);

// cloud_density.glsl
Real cloud_remap(Real x, Real lo);
Real2 cloud_weather(const CloudLayer& layer, Real3 p);
Real cloud_height_profile(Real h, Real type);
Real cloud_shape_density(const CloudLayer& layer, Real3 p, Real2 weather);
Real cloud_eroded_density(const CloudLayer& layer, Real3 p, Real shape_density);
Real cloud_density(const CloudLayer& layer, Real3 p);
Real cloud_extinction(const CloudLayer& layer, Real3 p);

// cloud_phase.glsl
Real draine_phase(Real g, Real alpha, Real nu);
Real3 cloud_mie_fit_lobes(Real d, Real& w_d);
Real cloud_phase(Real droplet_diameter_um, Real nu);

// cloud_scattering.glsl
Real cloud_octaves(Real phase, Real tau_sun, Real mu_s, int octaves);

}  // namespace planet::shared
