#pragma once
// The shared math's types and table sizes (atmosphere/shaders/definitions.glsl
// and lut_sizes.glsl) as C++ in double: the one description of a density
// profile and of the atmosphere that the model, the ground truth and the
// shaders all read.
#include <glm/glm.hpp>

namespace planet::shared {

using Real = double;
using Real2 = glm::dvec2;
using Real3 = glm::dvec3;

#include "atmosphere/shaders/definitions.glsl"
#include "atmosphere/shaders/lut_sizes.glsl"

}  // namespace planet::shared
