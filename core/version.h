#pragma once
// The program's version (CMake's project version), which files meant to
// be put together by other runs of the program carry: a share written by
// one build is not merged by another.
#include <string>

namespace planet {

std::string planet_version();

}  // namespace planet
