#include "core/progress.h"

#include <fmt/format.h>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

namespace planet {

namespace {
std::atomic<bool> g_shown{true};
ProgressObserver& observer() {
  static ProgressObserver o;
  return o;
}
}  // namespace

void set_progress_shown(bool shown) { g_shown = shown; }
void set_progress_observer(ProgressObserver o) { observer() = std::move(o); }
bool progress_shown() { return g_shown.load(); }

Progress::Progress(std::string label, double total, std::string unit, bool quiet)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      quiet_(quiet || !g_shown.load()),
      terminal_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

void Progress::begin_at(double done) {
  base_ = done;
  start_ = std::chrono::steady_clock::now();
}

void Progress::update(double done) {
  if (total_ <= 0 || (quiet_ && !observer())) return;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double rate = (done - base_) / std::max(elapsed, 1e-9);
  double left = rate > 0 ? (total_ - done) / rate : 0.0;
  // Nothing is known of the time left before anything is done.
  std::string time_left = rate > 0 ? fmt::format("  {:.0f} s left", left) : std::string();
  std::string rate_text = rate > 0 ? fmt::format("  {:.3g} {}s/s", rate, unit_) : std::string();
  std::string line;
  if (unit_.empty()) {
    line = fmt::format("{}: {:3.0f}%{}", label_, 100.0 * done / total_, time_left);
  } else if (total_ <= 1e4) {
    std::string count = done == std::floor(done) ? fmt::format("{:g}", done) : fmt::format("{:.1f}", done);
    line = fmt::format("{}: {} {}/{:g}  {:.2g} {}s/s{}", label_, unit_, count, total_, rate, unit_,
                       time_left);
  } else {
    // Large counts (paths) as a share and a rate.
    line = fmt::format("{}: {:3.0f}% of {:.3g} {}s{}{}", label_, 100.0 * done / total_, total_,
                       unit_, rate_text, time_left);
  }
  if (observer()) observer()(line, done / total_);
  if (quiet_) return;
  if (terminal_) {
    std::fprintf(stderr, "\r%s   ", line.c_str());
    std::fflush(stderr);
    open_ = true;
    return;
  }
  int tenths = int(std::floor(10.0 * done / total_));
  if (tenths != tenths_shown_ && (tenths > tenths_shown_ || done >= total_)) {
    tenths_shown_ = tenths;
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

void Progress::finish() {
  if (open_) std::fprintf(stderr, "\n");
  open_ = false;
}

}  // namespace planet
