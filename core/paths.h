#pragma once
// Files a command reads and folders it writes, checked before any long work
// starts: one InputError naming the path and the reason, instead of a
// library's message half-way through (a directory given as a file, a
// folder that cannot be made).
#include <filesystem>
#include <string>
#include <vector>

namespace planet {

// InputError unless `file` is a regular file this process can read.
void check_readable_file(const std::filesystem::path& file);

// An output folder made ready before the work: created with its missing
// parents and proven writable by writing a file into it. The folders it
// made are removed again (when still empty) unless keep() is called, so a
// run that fails leaves nothing behind. `what` names it in errors
// ("--out").
class OutputFolder {
 public:
  OutputFolder(std::filesystem::path dir, std::string what);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& path() const { return dir_; }
  void keep() { keep_ = true; }

 private:
  std::filesystem::path dir_;
  std::vector<std::filesystem::path> made_;  // innermost last
  bool keep_ = false;
};

}  // namespace planet
