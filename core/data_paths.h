#pragma once
// Where the program finds its shipped files (shaders, planets, flights).
// PLANET_ROOT in the environment overrides the source tree it was built from.
#include <filesystem>

namespace planet {

std::filesystem::path project_root();
std::filesystem::path data_dir();  // <root>/data

}  // namespace planet
