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

}  // namespace planet
