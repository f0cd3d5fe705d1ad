#include "atmosphere/gpu/bruneton/bruneton_cache.h"

#include "core/atomic_file.h"
#include "core/cache_dir.h"
#include "core/hash.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

namespace planet {

namespace {

constexpr const char* kMagic = "planet bruneton tables 1";

uint64_t checksum(const std::string& payload) {
  Fnv1a h;
  h.bytes(payload.data(), payload.size());
  return h.value();
}

}  // namespace

std::filesystem::path bruneton_cache_file(const std::string& key) {
  return cache_dir("bruneton") / (key + ".tables");
}

// A text header: magic, key, the tables' count and sizes; then the floats,
// then the payload's FNV-1a as 16 hex digits on the last line.
void write_bruneton_cache(const std::string& key, const std::vector<CachedTable>& tables) {
  std::string payload = fmt::format("{}\n{}\n{}\n", kMagic, key, tables.size());
  for (const auto& t : tables) payload += fmt::format("{} {} {}\n", t.width, t.height, t.depth);
  for (const auto& t : tables) {
    payload.append(reinterpret_cast<const char*>(t.rgba.data()), t.rgba.size() * sizeof(float));
  }
  std::string bytes = payload + fmt::format("\n{:016x}\n", checksum(payload));
  std::filesystem::path file = bruneton_cache_file(key);
  std::filesystem::create_directories(file.parent_path());
  write_file_atomically(file, bytes);
  if (uintmax_t limit = bruneton_cache_limit_bytes()) prune_bruneton_cache(limit, file);
}

namespace {

std::atomic<uintmax_t> cache_floor{0};

struct TableFile {
  std::filesystem::file_time_type used;
  uintmax_t bytes;
  std::filesystem::path file;
};

// The folder's table files, each with its size and when it was last used.
std::vector<TableFile> table_files() {
  std::vector<TableFile> files;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(cache_dir("bruneton"), ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    if (it->path().extension() != ".tables") continue;
    std::error_code e1, e2;
    uintmax_t bytes = it->file_size(e1);
    auto used = it->last_write_time(e2);
    if (!e1 && !e2) files.push_back({used, bytes, it->path()});
  }
  return files;
}

// $PLANET_BRUNETON_CACHE_MB in bytes, when it is set and a size.
std::optional<uintmax_t> limit_from_environment(bool say_why_not) {
  const char* env = std::getenv("PLANET_BRUNETON_CACHE_MB");
  if (!env || !*env) return std::nullopt;
  char* end = nullptr;
  double mb = std::strtod(env, &end);
  if (end != env && *end == '\0' && mb >= 0) return uintmax_t(mb * 1024.0 * 1024.0);
  if (say_why_not) {
    std::fprintf(stderr,
                 "planet: PLANET_BRUNETON_CACHE_MB='%s' is not a size in MB; 4096 is used\n", env);
  }
  return std::nullopt;
}

}  // namespace

uintmax_t bruneton_cache_limit_bytes() {
  if (auto limit = limit_from_environment(true)) return *limit;
  return std::max(uintmax_t(4096) * 1024 * 1024, cache_floor.load());
}

bool bruneton_cache_limit_from_environment() { return limit_from_environment(false).has_value(); }

void set_bruneton_cache_floor(uintmax_t bytes) { cache_floor = bytes; }

uintmax_t bruneton_cache_bytes() {
  uintmax_t total = 0;
  for (const TableFile& f : table_files()) total += f.bytes;
  return total;
}

int prune_bruneton_cache(uintmax_t limit, const std::filesystem::path& keep) {
  std::vector<TableFile> entries;
  uintmax_t total = 0;
  for (TableFile& f : table_files()) {
    total += f.bytes;
    if (f.file != keep) entries.push_back(std::move(f));
  }
  std::sort(entries.begin(), entries.end(),
            [](const TableFile& a, const TableFile& b) { return a.used < b.used; });
  int removed = 0;
  for (const TableFile& e : entries) {
    if (total <= limit) break;
    std::error_code e1;
    if (std::filesystem::remove(e.file, e1)) total -= e.bytes, ++removed;
  }
  return removed;
}

std::optional<std::vector<CachedTable>> read_bruneton_cache(const std::string& key,
                                                            const std::vector<CachedTable>& sizes) {
  std::filesystem::path file = bruneton_cache_file(key);
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string bytes = buffer.str();
  auto reject = [&](const char* what) -> std::optional<std::vector<CachedTable>> {
    std::fprintf(stderr, "planet: %s: %s; it is removed and the tables are computed again\n",
                 file.string().c_str(), what);
    std::error_code ec;
    std::filesystem::remove(file, ec);
    return std::nullopt;
  };
  // The checksum's line: "\n" + 16 hex digits + "\n".
  if (bytes.size() < 18 || bytes.back() != '\n') return reject("not a whole table file");
  std::string payload = bytes.substr(0, bytes.size() - 18);
  std::string stored = bytes.substr(bytes.size() - 17, 16);
  if (stored != fmt::format("{:016x}", checksum(payload))) {
    return reject("its checksum does not match its contents (a corrupt file)");
  }
  std::istringstream header(payload);
  std::string magic, stored_key;
  size_t count = 0;
  std::getline(header, magic);
  std::getline(header, stored_key);
  header >> count;
  if (magic != kMagic || stored_key != key || count != sizes.size()) {
    return reject("it holds other tables than its name says");
  }
  std::vector<CachedTable> tables(count);
  for (size_t i = 0; i < count; ++i) {
    header >> tables[i].width >> tables[i].height >> tables[i].depth;
    if (!header || tables[i].width != sizes[i].width || tables[i].height != sizes[i].height ||
        tables[i].depth != sizes[i].depth) {
      return reject("its tables' sizes are not the technique's");
    }
  }
  header.get();  // the header's last newline
  size_t at = size_t(header.tellg());
  for (auto& t : tables) {
    size_t floats = size_t(t.width) * size_t(t.height) * size_t(t.depth) * 4;
    if (at + floats * sizeof(float) > payload.size()) return reject("it is cut short");
    t.rgba.resize(floats);
    std::memcpy(t.rgba.data(), payload.data() + at, floats * sizeof(float));
    at += floats * sizeof(float);
  }
  if (at != payload.size()) return reject("it has bytes after its tables");
  // Used now: the last to go when the folder is pruned.
  std::error_code ec;
  std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ec);
  return tables;
}

}  // namespace planet
