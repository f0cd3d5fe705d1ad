#pragma once
// Progress of a long job on stderr, with its rate and the time left: on a
// terminal one line rewritten in place, in a log a line per tenth of the
// work. Every wait longer than a second shows one.
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace planet {

// Whether progress is shown at all (commands with --quiet turn it off, for
// the waits deep inside them too: a technique's precompute, say).
void set_progress_shown(bool shown);
bool progress_shown();

// Sees every update's line and the fraction done, shown or quiet: a window
// whose loop a long wait holds puts it in its title (fly, while a
// technique's tables are computed). One at a time; an empty one removes it.
using ProgressObserver = std::function<void(const std::string& line, double fraction)>;
void set_progress_observer(ProgressObserver observer);

// One part of a job of unlike parts (the lab's cells: a cell read back
// from an earlier run, then one of seconds, then one of a minute's tables):
// its kind, and what it is expected to cost before any part is timed, in
// any unit (only the ratios count); 0: it costs nothing (work kept from
// before).
struct ProgressPart {
  std::string kind;
  double prior = 1;
};

// The time left of such a job. A part not done is expected to take the
// mean time of the finished parts of its kind where there are any, else
// its prior at the seconds per unit of prior that the finished parts took:
// a cheap first part and dear later ones give neither a tiny time left nor
// a jump, as the parts' count alone would.
class PartsEstimate {
 public:
  explicit PartsEstimate(std::vector<ProgressPart> parts);
  // Part `index` took `seconds` (parts of prior 0 teach nothing).
  void finished(size_t index, double seconds);
  // The expected seconds of the parts from `next` on, less `spent` already
  // on part `next`; nothing before any part of a prior has finished.
  std::optional<double> seconds_left(size_t next, double spent = 0) const;
  size_t size() const { return parts_.size(); }
  double prior(size_t index) const { return parts_[index].prior; }

 private:
  double expected(size_t index) const;
  std::vector<ProgressPart> parts_;
  std::map<std::string, std::pair<double, int>> kinds_;  // seconds, parts
  double seconds_ = 0, priors_ = 0;                      // of the finished parts
};

class Progress {
 public:
  // `label` names the job ("capture ascent"); `total` is its size in
  // `unit`s ("frame": "frame 3/41  1.2 frames/s"), or with no unit a
  // fraction shown in percent. Quiet prints nothing.
  Progress(std::string label, double total, std::string unit = "", bool quiet = false);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // A job that goes on from earlier work starts with this much done: the
  // rate and the time left count from here.
  void begin_at(double done);
  // The total is this many parts (one a unit), unlike in cost: the time
  // left counts from their costs (PartsEstimate), not their number.
  void expect_parts(std::vector<ProgressPart> parts);
  // `done` of the total so far.
  void update(double done);
  // Ends the line on a terminal; the last update should have been the total.
  void finish();

 private:
  std::string label_, unit_;
  double total_;
  bool quiet_, terminal_, open_ = false;
  int tenths_shown_ = -1;
  double base_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::optional<PartsEstimate> parts_;
  size_t parts_done_ = 0;                             // parts finished by the last update
  std::chrono::steady_clock::time_point part_start_;  // when the part now under way began
};

}  // namespace planet
