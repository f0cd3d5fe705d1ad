#include "core/cache_dir.h"

#include <cstdlib>

namespace planet {

std::filesystem::path cache_dir(const std::string& what) {
  if (const char* dir = std::getenv("PLANET_CACHE_DIR"); dir && *dir) {
    return std::filesystem::path(dir) / what;
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    return std::filesystem::path(xdg) / "planet" / what;
  }
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".cache" / "planet" / what;
}

}  // namespace planet
