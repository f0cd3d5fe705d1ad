#include "core/version.h"

namespace planet {

std::string planet_version() { return PLANET_VERSION; }

}  // namespace planet
