#include "gl/pass_graph.h"

#include <fmt/format.h>

#include <stdexcept>

namespace planet {

std::vector<size_t> pass_order(const std::vector<Pass>& passes) {
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < passes.size(); ++i) {
    if (!index.emplace(passes[i].name, i).second) {
      throw std::logic_error(fmt::format("the frame has two passes named \"{}\"", passes[i].name));
    }
  }
  // Depth-first, in the order given: a pass's reads are placed before it.
  enum class Mark { kNone, kVisiting, kPlaced };
  std::vector<Mark> mark(passes.size(), Mark::kNone);
  std::vector<size_t> order;
  order.reserve(passes.size());
  std::function<void(size_t)> place = [&](size_t i) {
    if (mark[i] == Mark::kPlaced) return;
    if (mark[i] == Mark::kVisiting) {
      throw std::logic_error(fmt::format("the pass \"{}\" reads its own result", passes[i].name));
    }
    mark[i] = Mark::kVisiting;
    for (const std::string& read : passes[i].reads) {
      auto it = index.find(read);
      if (it == index.end()) {
        throw std::logic_error(
            fmt::format("the pass \"{}\" reads \"{}\", which the frame lacks", passes[i].name, read));
      }
      place(it->second);
    }
    mark[i] = Mark::kPlaced;
    order.push_back(i);
  };
  for (size_t i = 0; i < passes.size(); ++i) place(i);
  return order;
}

void PassGraph::run(std::vector<Pass> passes, PassRecorder& recorder) {
  for (size_t i : pass_order(passes)) {
    Pass& pass = passes[i];
    if (pass.needed && !pass.needed()) {
      recorder.skip(pass.name);
      continue;
    }
    if (pass.inputs) {
      PassKey key = pass.inputs();
      for (const std::string& read : pass.reads) key.add(runs(read));
      if (!inputs_.changed(pass.name, key)) {
        recorder.reuse(pass.name);
        continue;
      }
    }
    if (!pass.times_itself) recorder.begin(pass.name);
    pass.run();
    if (!pass.times_itself) recorder.end();
    ++runs_[pass.name];
  }
}

void PassGraph::forget() {
  inputs_.forget();
  runs_.clear();
}

uint64_t PassGraph::runs(const std::string& pass) const {
  auto it = runs_.find(pass);
  return it == runs_.end() ? 0 : it->second;
}

}  // namespace planet
