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

// Removes from `dir` what a killed writer left: the ".partial-<pid>-*"
// files and ".staging-<pid>" folders of processes that no longer run. A
// job that writes into `dir` calls it first, so that a folder a killed run
// is resumed into ends as the folder of a run that never stopped.
void remove_stale_partials(const std::filesystem::path& dir);

// A folder of this process's own inside `dir` (".staging-<pid>"), made on
// construction and removed with what is left in it on destruction: a job
// writes the files of one result there, each whole, then moves them into
// `dir` together (a frame's image, depth and sidecar).
class StagingFolder {
 public:
  explicit StagingFolder(const std::filesystem::path& dir);
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Renames path()/name to dir/name.
  void publish(const std::string& name) const;
  // A message about a file in here (a failed write) as one about the file
  // it stands for in `dir`: the user knows no staging folder.
  std::string as_published(const std::string& message) const;
  // Removes the folder and what is left in it now, as destruction would: a
  // job calls it once its last result is published, so that a kill in
  // what it does after (its summary, tearing down GL) leaves no staging.
  void remove() const;

 private:
  std::filesystem::path dir_, path_;
};

}  // namespace planet
