#pragma once
// Progress of a long job on stderr, with its rate and the time left: on a
// terminal one line rewritten in place, in a log a line per tenth of the
// work. Every wait longer than a second shows one.
#include <chrono>
#include <functional>
#include <string>

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
};

}  // namespace planet
