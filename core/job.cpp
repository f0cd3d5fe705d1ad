#include "core/job.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>

namespace planet {

bool share_owns(const Share& share, ShareSplit split, int index, int total) {
  if (split == ShareSplit::kInterleaved) return index % share.count == share.index;
  auto [first, end] = share_range(share, total);
  return index >= first && index < end;
}

Job::Job(std::filesystem::path dir, const std::vector<JobCell>& plan, JobOptions options)
    : dir_(std::move(dir)), options_(options) {
  // The groups in the order they first come; a share owns whole groups.
  std::map<std::string, int> groups;
  std::set<std::string> keys;
  for (const JobCell& cell : plan) {
    if (!keys.insert(cell.key).second) {
      throw InputError(
          fmt::format("{}: the job's plan names the cell {} twice", dir_.string(), cell.key));
    }
    groups.try_emplace(cell.group.empty() ? "\n" + cell.key : cell.group, int(groups.size()));
  }
  for (const JobCell& cell : plan) {
    int group = groups.at(cell.group.empty() ? "\n" + cell.key : cell.group);
    if (share_owns(options_.share, options_.split, group, int(groups.size()))) {
      cells_.push_back(cell);
    }
  }
}

bool Job::finished(const JobCell& cell) const {
  return !options_.redo && std::filesystem::exists(file(cell));
}

int Job::left() const {
  int left = 0;
  for (const JobCell& cell : cells_) left += finished(cell) ? 0 : 1;
  return left;
}

std::vector<ProgressPart> Job::parts(std::vector<ProgressPart> priors) const {
  for (size_t i = 0; i < cells_.size() && i < priors.size(); ++i) {
    if (finished(cells_[i])) priors[i].prior = 0;
  }
  return priors;
}

void Job::run(const JobSteps& steps) const {
  // What a run killed while writing left: gone before any cell is judged.
  std::set<std::filesystem::path> folders = {dir_};
  for (const JobCell& cell : cells_) folders.insert(file(cell).parent_path());
  for (const std::filesystem::path& folder : folders) {
    if (std::filesystem::is_directory(folder)) remove_stale_partials(folder);
  }
  const int total = int(cells_.size());
  std::string prepared;
  bool any_prepared = false;
  for (int i = 0; i < total; ++i) {
    const JobCell& cell = cells_[size_t(i)];
    if (steps.progress) steps.progress(i, total, cell.label);
    const std::filesystem::path result = file(cell);
    if (finished(cell) && (!steps.keep || steps.keep(cell, result))) continue;
    std::string group = cell.group.empty() ? "\n" + cell.key : cell.group;
    if (!any_prepared || group != prepared) {
      if (steps.prepare) steps.prepare(cell);
      prepared = group;
      any_prepared = true;
    }
    std::string bytes = steps.run(cell);
    std::filesystem::create_directories(result.parent_path());
    // Whole or not at all: a killed job never leaves half a cell.
    write_file_atomically(result, bytes);
  }
  if (steps.progress) steps.progress(total, total, "");
}

JobProgress::JobProgress(std::string label, std::string unit, std::string done, bool quiet,
                         std::filesystem::path kept_in, std::function<void()> on_stop)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      done_(std::move(done)),
      quiet_(quiet),
      kept_in_(std::move(kept_in)),
      on_stop_(std::move(on_stop)) {}

void JobProgress::update(int done, int total) {
  if (!progress_) {
    progress_.emplace(label_, total, unit_, quiet_);
    if (!parts_.empty()) progress_->expect_parts(parts_);
  }
  progress_->update(done);
  if (!interrupt_.interrupted()) return;
  progress_->finish();
  if (on_stop_) on_stop_();
  std::fprintf(stderr,
               "planet: interrupted: %d of %d %s are done and kept in %s; run the same command "
               "again to go on\n",
               done, total, done_.c_str(), kept_in_.string().c_str());
  std::exit(kInterruptedExitStatus);
}

void JobProgress::finish() {
  if (progress_) progress_->finish();
}

InputError not_a_job_cell(const std::string& file, const std::string& job, const std::string& why) {
  return InputError(
      fmt::format("{}: not a cell of {} ({}); delete it or run with --redo", file, job, why));
}

nlohmann::json read_job_file(const std::filesystem::path& file, const std::string& job) {
  std::ifstream in(file);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw not_a_job_cell(file.string(), job, e.what());
  }
}

}  // namespace planet
