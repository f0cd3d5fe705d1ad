#pragma once
// Where the program keeps what it can compute again but would rather not:
// $PLANET_CACHE_DIR/<what> if set, else $XDG_CACHE_HOME/planet/<what>, else
// ~/.cache/planet/<what> (path-traced references, precomputed tables).
#include <filesystem>
#include <string>

namespace planet {

std::filesystem::path cache_dir(const std::string& what);

}  // namespace planet
