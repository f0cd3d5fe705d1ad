#include "core/data_paths.h"

#include <cstdlib>

namespace planet {

std::filesystem::path project_root() {
  if (const char* env = std::getenv("PLANET_ROOT"); env && *env) return env;
  return PLANET_ROOT_DIR;
}

std::filesystem::path data_dir() { return project_root() / "data"; }

}  // namespace planet
