// The sea's BRDF's one C++ translation unit: the GLSL file compiled in
// double (see sea_brdf.h).
#include "terrain/sea_brdf.h"

#include <glm/gtc/constants.hpp>

namespace planet::sea {

using namespace glm;
const Real kPi = glm::pi<Real>();
#include "terrain/shaders/sea_brdf.glsl"

}  // namespace planet::sea
