#include "core/data_paths.h"

#include <cstdlib>
#include <system_error>

namespace planet {

namespace {

// <prefix>/share/planet when this program is <prefix>/bin/planet and the
// install left its data there; empty otherwise.
std::filesystem::path installed_root() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || !exe.has_parent_path()) return {};
  std::filesystem::path share = exe.parent_path().parent_path() / "share" / "planet";
  if (!std::filesystem::is_directory(share / "data", ec)) return {};
  return share;
}

}  // namespace

std::filesystem::path project_root() {
  if (const char* env = std::getenv("PLANET_ROOT"); env && *env) return env;
  static const std::filesystem::path installed = installed_root();
  if (!installed.empty()) return installed;
  return PLANET_ROOT_DIR;
}

std::filesystem::path data_dir() { return project_root() / "data"; }

}  // namespace planet
