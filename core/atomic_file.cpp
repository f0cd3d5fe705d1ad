#include "core/atomic_file.h"

#include <unistd.h>

#include "core/error.h"

#include <fmt/format.h>

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
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) {
      out.close();
      std::error_code ec;
      std::filesystem::remove(partial, ec);
      throw SystemError(fmt::format("{}: cannot write", file.string()));
    }
  }
  std::filesystem::rename(partial, file);
}

}  // namespace planet
