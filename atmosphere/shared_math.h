#pragma once
// atmosphere/shaders/atmosphere_functions.glsl compiled as C++ in double
// precision: the CPU side of the shared math (Bruneton's reference
// implementation does the same with its functions.glsl).
#include "atmosphere/model.h"

#include <glm/glm.hpp>

namespace planet::shared {

using namespace glm;
using Real = double;
using Real3 = glm::dvec3;
#define IN(T) const T&
#define OUT(T) T&
#include "atmosphere/shaders/atmosphere_functions.glsl"
#undef IN
#undef OUT

// The model as the shared functions see it.
Atmosphere to_shared(const AtmosphereModel& model);

}  // namespace planet::shared
