#include "core/paths.h"

#include "core/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace planet {

void check_readable_file(const std::filesystem::path& file) {
  std::error_code ec;
  auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) {
    throw InputError(fmt::format("{}: cannot open file: no such file", file.string()));
  }
  if (std::filesystem::is_directory(status)) {
    throw InputError(fmt::format("{}: cannot open file: it is a directory", file.string()));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError(fmt::format("{}: cannot open file: {}", file.string(), std::strerror(errno)));
  }
}

OutputFolder::OutputFolder(std::filesystem::path dir, std::string what) : dir_(std::move(dir)) {
  auto fail = [&](const std::string& reason) {
    throw InputError(fmt::format("{} {}: {}", what, dir_.string(), reason));
  };
  if (dir_.empty()) dir_ = ".";
  std::error_code ec;
  // The folders that are missing, outermost first.
  std::vector<std::filesystem::path> missing;
  for (auto p = std::filesystem::absolute(dir_, ec); !p.empty(); p = p.parent_path()) {
    auto status = std::filesystem::status(p, ec);
    if (std::filesystem::exists(status)) {
      if (!std::filesystem::is_directory(status)) {
        fail(fmt::format("cannot be a folder: {} is a file", p.string()));
      }
      break;
    }
    missing.insert(missing.begin(), p);
    if (p == p.parent_path()) break;
  }
  for (const auto& p : missing) {
    // Another process may make the same folder meanwhile (the tasks of a
    // cluster's job array write into one): a folder that is there is
    // fine, and is not ours to remove.
    bool made = std::filesystem::create_directory(p, ec);
    std::error_code exists_ec;
    if (ec || (!made && !std::filesystem::is_directory(p, exists_ec))) {
      std::string reason = ec ? ec.message() : "it could not be made";
      for (auto it = made_.rbegin(); it != made_.rend(); ++it) std::filesystem::remove(*it, ec);
      made_.clear();
      fail(fmt::format("cannot create the folder: {}", reason));
    }
    if (made) made_.push_back(p);
  }
  auto probe = dir_ / ".planet-write-test";
  {
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    out << "planet";
    if (!out) {
      int error = errno;
      out.close();
      std::filesystem::remove(probe, ec);
      for (auto it = made_.rbegin(); it != made_.rend(); ++it) std::filesystem::remove(*it, ec);
      made_.clear();
      fail(fmt::format("cannot write into the folder: {}", std::strerror(error)));
    }
  }
  std::filesystem::remove(probe, ec);
}

OutputFolder::~OutputFolder() {
  if (keep_) return;
  std::error_code ec;
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) {
    if (std::filesystem::is_empty(*it, ec)) std::filesystem::remove(*it, ec);
  }
}

}  // namespace planet
