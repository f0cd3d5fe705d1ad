#pragma once
// The bruneton technique's tables on disk: precomputed once per model and
// quality (seconds to a minute), read back in milliseconds. One file per
// key in cache_dir("bruneton"), written whole or not at all; a file whose
// checksum or sizes do not match is reported, deleted and rebuilt, never
// used.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace planet {

// A table as RGBA floats and its size (depth 1 for 2D).
struct CachedTable {
  int width = 0, height = 0, depth = 1;
  std::vector<float> rgba;
};

std::filesystem::path bruneton_cache_file(const std::string& key);

// The tables kept under `key`, in order, or nothing when there are none;
// with the sizes the caller expects. A file that is not whole (its size,
// header or checksum wrong) prints one line saying so on stderr, is
// removed, and gives nothing.
std::optional<std::vector<CachedTable>> read_bruneton_cache(const std::string& key,
                                                            const std::vector<CachedTable>& sizes);
void write_bruneton_cache(const std::string& key, const std::vector<CachedTable>& tables);

}  // namespace planet
