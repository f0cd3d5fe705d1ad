#include "gl/pass_tally.h"

#include <fmt/format.h>

#include <algorithm>

namespace planet {

void PassTally::add(const std::vector<PassTiming>& frame) {
  ++frames_;
  for (const PassTiming& p : frame) {
    Pass& pass = passes_[p.pass];
    if (p.reused || p.skipped) {
      ++(p.reused ? pass.reused : pass.skipped);
      continue;
    }
    ++pass.ran;
    pass.gpu_ms += p.gpu_ms;
    pass.wall_ms += p.wall_ms;
  }
}

std::string PassTally::summary() const {
  struct Row {
    std::string name;
    double mean_ms;
    const Pass* pass;
  };
  std::vector<Row> rows;
  size_t width = 0;
  for (const auto& [name, pass] : passes_) {
    double total = pass.wall_ms > 0 ? pass.wall_ms : pass.gpu_ms;
    rows.push_back({name, pass.ran > 0 ? total / pass.ran : 0.0, &pass});
    width = std::max(width, name.size());
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.mean_ms > b.mean_ms; });
  std::string out;
  for (const Row& r : rows) {
    out += fmt::format("  {:<{}}  {:8.2f} ms  ran {} of {}", r.name, width, r.mean_ms, r.pass->ran,
                       frames_);
    if (r.pass->reused > 0) out += fmt::format(", reused {}", r.pass->reused);
    if (r.pass->skipped > 0) out += fmt::format(", skipped {}", r.pass->skipped);
    out += "\n";
  }
  return out;
}

std::string PassTally::table() const {
  if (frames_ == 0) return "";
  struct Row {
    std::string name;
    double wall_ms, gpu_ms;
    const Pass* pass;
  };
  std::vector<Row> rows;
  size_t width = std::string("frame").size();
  double frame_wall = 0, frame_gpu = 0;
  for (const auto& [name, pass] : passes_) {
    const double ran = std::max(pass.ran, 1);
    rows.push_back({name, pass.wall_ms / ran, pass.gpu_ms / ran, &pass});
    width = std::max(width, name.size());
    frame_wall += pass.wall_ms;
    frame_gpu += pass.gpu_ms;
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return std::max(a.wall_ms, a.gpu_ms) > std::max(b.wall_ms, b.gpu_ms);
  });
  // A wall time of 0 for a pass that ran: the timer was not synchronous.
  auto wall = [](double ms, bool kept) {
    return kept ? fmt::format("{:10.2f}", ms) : fmt::format("{:>10}", "-");
  };
  std::string out = fmt::format("  {:<{}}  {:>10}  {:>10}  {:>5}  {:>6}  {:>7}\n", "pass", width,
                                "wall ms", "GPU ms", "ran", "reused", "skipped");
  for (const Row& r : rows) {
    out += fmt::format("  {:<{}}  {}  {:10.2f}  {:5}  {:6}  {:7}\n", r.name, width,
                       wall(r.wall_ms, r.pass->wall_ms > 0 || r.pass->ran == 0), r.gpu_ms,
                       r.pass->ran, r.pass->reused, r.pass->skipped);
  }
  out += fmt::format("  {:<{}}  {}  {:10.2f}  {:>5}\n", "frame", width,
                     wall(frame_wall / frames_, frame_wall > 0), frame_gpu / frames_,
                     fmt::format("{}", frames_));
  return out;
}

}  // namespace planet
