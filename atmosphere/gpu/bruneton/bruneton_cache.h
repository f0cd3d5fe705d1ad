#pragma once
// The bruneton technique's tables on disk: precomputed once per model and
// quality (seconds to a minute), read back in milliseconds. One file per
// key in cache_dir("bruneton"), written whole or not at all; a file whose
// checksum or sizes do not match is reported, deleted and rebuilt, never
// used. The folder is kept under a size (bruneton_cache_limit_bytes): a
// write that takes it over removes the files used longest ago.
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

// The most the folder keeps: $PLANET_BRUNETON_CACHE_MB megabytes if set (0:
// no limit), else 4096 MB (some thirty tables of the default quality) or
// the floor this process set, whichever is more.
uintmax_t bruneton_cache_limit_bytes();
bool bruneton_cache_limit_from_environment();
// For the rest of this process, keeps at least `bytes` where the
// environment sets no limit: a sweep that reads its tables again (the
// lab's) needs them all kept, or each is pushed out before it is read.
void set_bruneton_cache_floor(uintmax_t bytes);
// The bytes of the tables in the folder now.
uintmax_t bruneton_cache_bytes();
// Removes the files read or written longest ago until the folder's tables
// fit in `limit` bytes, the file `keep` aside; returns how many it removed.
int prune_bruneton_cache(uintmax_t limit, const std::filesystem::path& keep);

}  // namespace planet
