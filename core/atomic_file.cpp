#include "core/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include "core/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace planet {

std::filesystem::path partial_file(const std::filesystem::path& file) {
  // The process's id in the name: two programs writing the same file (two
  // tests filling one cache) each rename a whole file of their own.
  return file.parent_path() /
         (".partial-" + std::to_string(getpid()) + "-" + file.filename().string());
}

void write_file_atomically(const std::filesystem::path& file, const std::string& bytes) {
  std::filesystem::path partial = partial_file(file);
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    errno = 0;
    out.write(bytes.data(), std::streamsize(bytes.size()));
    // The last bytes reach the disk at close: a full disk may say so only then.
    out.close();
    if (!out) {
      int error = errno;
      std::error_code ec;
      std::filesystem::remove(partial, ec);
      throw SystemError(fmt::format("{}: cannot write: {}", file.string(),
                                    error ? std::strerror(error) : "the write failed"));
    }
  }
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    throw SystemError(fmt::format("{}: cannot put in place: {}", file.string(), ec.message()));
  }
}

namespace {

// The pid in ".partial-<pid>-..." or ".staging-<pid>", or 0.
pid_t writer_of(const std::string& name) {
  for (const char* prefix : {".partial-", ".staging-"}) {
    std::string p = prefix;
    if (name.rfind(p, 0) != 0) continue;
    size_t end = name.find_first_not_of("0123456789", p.size());
    std::string digits = name.substr(p.size(), end == std::string::npos ? end : end - p.size());
    if (digits.empty() || digits.size() > 9) return 0;
    return pid_t(std::stol(digits));
  }
  return 0;
}

}  // namespace

void remove_stale_partials(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    pid_t pid = writer_of(entry.path().filename().string());
    if (pid <= 0 || pid == getpid()) continue;
    if (kill(pid, 0) == 0 || errno != ESRCH) continue;  // still running (or not ours to ask)
    std::filesystem::remove_all(entry.path(), ec);
  }
}

StagingFolder::StagingFolder(const std::filesystem::path& dir)
    : dir_(dir), path_(dir / (".staging-" + std::to_string(getpid()))) {
  std::error_code ec;
  std::filesystem::create_directories(path_, ec);
  if (ec) {
    throw SystemError(fmt::format("{}: cannot create: {}", path_.string(), ec.message()));
  }
}

StagingFolder::~StagingFolder() { remove(); }

void StagingFolder::remove() const {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

void StagingFolder::publish(const std::string& name) const {
  std::error_code ec;
  std::filesystem::rename(path_ / name, dir_ / name, ec);
  if (ec) {
    throw SystemError(
        fmt::format("{}: cannot put in place: {}", (dir_ / name).string(), ec.message()));
  }
}

std::string StagingFolder::as_published(const std::string& message) const {
  std::string out = message;
  for (const std::string& from :
       {(path_ / (".partial-" + std::to_string(getpid()) + "-")).string(), (path_ / "").string()}) {
    for (size_t at = out.find(from); at != std::string::npos; at = out.find(from, at)) {
      std::string to = (dir_ / "").string();
      out.replace(at, from.size(), to);
      at += to.size();
    }
  }
  return out;
}

}  // namespace planet
