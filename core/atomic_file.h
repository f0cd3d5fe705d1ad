#pragma once
// Files that are either whole or absent: written under a neighbouring
// temporary name (".partial-<pid>-<name>") and renamed into place, so that a
// program killed while writing leaves the last whole file, never half of
// one that looks finished.
#include <filesystem>
#include <string>

namespace planet {

void write_file_atomically(const std::filesystem::path& file, const std::string& bytes);

// The neighbour a file is written under before it is renamed.
std::filesystem::path partial_file(const std::filesystem::path& file);

}  // namespace planet
