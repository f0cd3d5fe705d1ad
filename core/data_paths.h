#pragma once
// Where the program finds its shipped files (shaders, planets, flights,
// references), in this order:
// - PLANET_ROOT in the environment;
// - <prefix>/share/planet beside an installed program (<prefix>/bin/planet,
//   as `cmake --install` lays it out), so that it runs outside its source tree;
// - the source tree it was built from.
#include <filesystem>

namespace planet {

std::filesystem::path project_root();
std::filesystem::path data_dir();  // <root>/data

}  // namespace planet
