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

PartsEstimate::PartsEstimate(std::vector<ProgressPart> parts) : parts_(std::move(parts)) {}

void PartsEstimate::finished(size_t index, double seconds) {
  const ProgressPart& part = parts_.at(index);
  if (!(part.prior > 0)) return;
  auto& [sum, count] = kinds_[part.kind];
  sum += seconds;
  ++count;
  seconds_ += seconds;
  priors_ += part.prior;
}

double PartsEstimate::expected(size_t index) const {
  const ProgressPart& part = parts_[index];
  if (!(part.prior > 0)) return 0.0;
  auto kind = kinds_.find(part.kind);
  if (kind != kinds_.end()) return kind->second.first / kind->second.second;
  return part.prior * seconds_ / priors_;
}

std::optional<double> PartsEstimate::seconds_left(size_t next, double spent) const {
  if (!(priors_ > 0)) return std::nullopt;
  double left = 0;
  for (size_t i = next; i < parts_.size(); ++i) {
    // The part under way: what it is expected to take beyond what it has.
    left += i == next ? std::max(expected(i) - spent, 0.0) : expected(i);
  }
  return left;
}

Progress::Progress(std::string label, double total, std::string unit, bool quiet)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      quiet_(quiet || !g_shown.load()),
      terminal_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      part_start_(start_) {}

Progress::~Progress() { finish(); }

void Progress::begin_at(double done) {
  base_ = done;
  start_ = std::chrono::steady_clock::now();
  part_start_ = start_;
  parts_done_ = size_t(std::max(done, 0.0));
}

void Progress::expect_parts(std::vector<ProgressPart> parts) {
  parts_.emplace(std::move(parts));
  parts_done_ = size_t(std::max(base_, 0.0));
  part_start_ = std::chrono::steady_clock::now();
}

void Progress::update(double done) {
  if (total_ <= 0 || (quiet_ && !observer())) return;
  auto now = std::chrono::steady_clock::now();
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double rate = (done - base_) / std::max(elapsed, 1e-9);
  // Nothing is known of the time left before anything is done.
  std::optional<double> left;
  if (rate > 0) left = (total_ - done) / rate;
  if (parts_) {
    // Parts of unlike cost: the time since the last part ended is the
    // parts' finished since, shared by their priors.
    size_t finished = std::min(size_t(std::max(std::floor(done), 0.0)), parts_->size());
    if (finished > parts_done_) {
      double seconds = std::chrono::duration<double>(now - part_start_).count(), priors = 0;
      for (size_t i = parts_done_; i < finished; ++i) priors += std::max(parts_->prior(i), 0.0);
      for (size_t i = parts_done_; i < finished; ++i) {
        if (priors > 0) parts_->finished(i, seconds * std::max(parts_->prior(i), 0.0) / priors);
      }
      parts_done_ = finished;
      part_start_ = now;
    }
    left = parts_->seconds_left(finished, std::chrono::duration<double>(now - part_start_).count());
  }
  std::string time_left = left ? fmt::format("  {:.0f} s left", *left) : std::string();
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
