#pragma once
// The engine of the long jobs (the lab's sweep, the stability map, the
// governor's check, the measured skies): a plan of cells, each named by a
// key that is the path of its result under the job's folder. A cell whose
// result is there is kept, not run again (but with redo); each result is
// written whole or not at all (atomic_file.h), so that a job killed
// anywhere goes on where it stopped and ends with the bytes of a run that
// never stopped; a share K/N of the job owns a part of the cells known from
// K and N alone (share.h), so shares run in any order, anywhere, and again.
// The shares' results put together are checked with require_one_job and
// shares_by_index (share.h).
#include "core/error.h"
#include "core/interrupt.h"
#include "core/progress.h"
#include "core/share.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct JobCell {
  std::string key;    // its result under the job's folder: "cells/earth_noon/raymarch-cheap.json"
  std::string label;  // what progress names: "earth_noon raymarch:cheap"
  // Cells of one group share what JobSteps::prepare makes for them (a
  // scene's ground truth), and a share owns whole groups; empty: the cell
  // is a group of its own.
  std::string group;
  size_t index = 0;  // the cell's place in its user's own plan (a scene and a point, say)
};

// How a share owns its part of a plan's groups: every N-th from K (groups
// of unlike cost spread over the shares), or a contiguous run (share_range).
enum class ShareSplit { kInterleaved, kContiguous };

// Whether `share` owns item `index` of `total`.
bool share_owns(const Share& share, ShareSplit split, int index, int total);

struct JobOptions {
  bool redo = false;  // every cell of the share run again, its result replaced
  Share share;        // the part of the plan this run owns
  ShareSplit split = ShareSplit::kInterleaved;
};

struct JobSteps {
  // Before the first cell of a group that runs (none where all its cells
  // are kept): what the group's cells share.
  std::function<void(const JobCell&)> prepare;
  // Runs the cell: its result, the bytes of its file.
  std::function<std::string(const JobCell&)> run;
  // A kept cell's result, read back; false where it is not whole, and the
  // cell runs again. None: kept cells are not read.
  std::function<bool(const JobCell&, const std::filesystem::path&)> keep;
  // Before each cell: (cells done, cells in all, the cell's label); after
  // the last, (all, all, "").
  std::function<void(int, int, const std::string&)> progress;
};

class Job {
 public:
  // The plan's cells in order; the share's are kept. InputError naming the
  // key for a key given twice.
  Job(std::filesystem::path dir, const std::vector<JobCell>& plan, JobOptions options = {});

  const std::filesystem::path& dir() const { return dir_; }
  // This share's cells, in the plan's order.
  const std::vector<JobCell>& cells() const { return cells_; }
  std::filesystem::path file(const JobCell& cell) const { return dir_ / cell.key; }
  // Whether the cell's result is there and kept (never with redo).
  bool finished(const JobCell& cell) const;
  // The cells of the share that will run.
  int left() const;
  // What the progress line's time left weighs each of the share's cells
  // by (Progress::expect_parts): `priors` in the cells' order, with 0 for a
  // cell kept from before.
  std::vector<ProgressPart> parts(std::vector<ProgressPart> priors) const;

  // Removes what a killed run left in the folders of the cells
  // (remove_stale_partials), then runs the share's cells not finished,
  // each result written whole, and reads the others back.
  void run(const JobSteps& steps) const;

 private:
  std::filesystem::path dir_;
  std::vector<JobCell> cells_;
  JobOptions options_;
};

// A job's progress line for the command that runs it (Progress: the rate
// and the time left), and its Ctrl-C: while it lives SIGINT is held
// (InterruptScope); at the next cell the line ends, `on_stop` runs (the
// command keeps its output folder), "planet: interrupted: D of T <done>
// are done and kept in <kept_in>; run the same command again to go on" is
// said, and the program exits with kInterruptedExitStatus.
class JobProgress {
 public:
  JobProgress(std::string label, std::string unit, std::string done, bool quiet,
              std::filesystem::path kept_in, std::function<void()> on_stop = {});
  // What the time left weighs each cell by (Job::parts), before any update.
  void expect_parts(std::vector<ProgressPart> parts) { parts_ = std::move(parts); }
  // JobSteps::progress: the line made at the first update, with its total.
  void update(int done, int total);
  std::function<void(int, int, const std::string&)> steps() {
    return [this](int done, int total, const std::string&) { update(done, total); };
  }
  bool interrupted() const { return interrupt_.interrupted(); }
  void finish();

 private:
  std::string label_, unit_, done_;
  bool quiet_;
  std::filesystem::path kept_in_;
  std::function<void()> on_stop_;
  std::vector<ProgressPart> parts_;
  InterruptScope interrupt_;
  std::optional<Progress> progress_;
};

// A cell's result read back from JSON by `read`: a file that does not parse,
// or a field `read` finds missing or of another type (a nlohmann::json
// exception), is InputError "FILE: not a cell of JOB (WHY); delete it or
// run with --redo".
InputError not_a_job_cell(const std::string& file, const std::string& job, const std::string& why);
template <class Read>
auto read_job_json(const nlohmann::json& json, const std::string& file, const std::string& job,
                   Read read) -> decltype(read(json)) {
  try {
    return read(json);
  } catch (const nlohmann::json::exception& e) {
    throw not_a_job_cell(file, job, e.what());
  }
}
nlohmann::json read_job_file(const std::filesystem::path& file, const std::string& job);

}  // namespace planet
