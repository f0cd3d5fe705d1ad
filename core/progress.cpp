#include "core/progress.h"

#include <fmt/format.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace planet {

Progress::Progress(std::string label, double total, std::string unit, bool quiet)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      quiet_(quiet),
      terminal_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

void Progress::update(double done) {
  if (quiet_ || total_ <= 0) return;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double rate = done / std::max(elapsed, 1e-9);
  double left = done > 0 ? (total_ - done) / rate : 0.0;
  std::string line = unit_.empty() ? fmt::format("{}: {:3.0f}%  {:.0f} s left", label_,
                                                 100.0 * done / total_, left)
                                   : fmt::format("{}: {} {:g}/{:g}  {:.1f} {}s/s  {:.0f} s left",
                                                 label_, unit_, done, total_, rate, unit_, left);
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
