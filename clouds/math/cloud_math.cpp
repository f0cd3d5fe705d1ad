// The shared cloud math's one C++ translation unit: the GLSL files compiled
// in double (see cloud_math.h).
#include "clouds/math/cloud_math.h"

#include "atmosphere/math/shared_math.h"

namespace planet::shared {

using namespace glm;
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
// clang-format off
#include "clouds/shaders/cloud_noise.glsl"
#include "clouds/shaders/cloud_density.glsl"
#include "clouds/shaders/cloud_phase.glsl"
#include "clouds/shaders/cloud_scattering.glsl"
// clang-format on
#undef IN
#undef OUT
#undef INOUT

}  // namespace planet::shared
