#pragma once
// A frame's passes as a graph. Each pass says which passes' results it
// reads, whether the frame needs it, and what its inputs are; the graph
// puts every pass after those it reads, skips the ones not needed, reuses
// the ones whose inputs are those of their last run, and runs the rest.
// What ran, was reused or was skipped is told to one recorder (GpuTimer),
// so a frame's table of passes comes from one place.
//
// A pass with inputs keeps its result between frames: it runs again when
// its own inputs change, or when a pass it reads ran since (the graph adds
// that pass's run count to the inputs: a table built from a rebuilt table
// is rebuilt too). A pass without inputs runs whenever it is needed.
// Inputs are bytes (PassKey), compared exactly: what a pass computes
// depends on the current frame alone, never on the frames before it, so a
// capture's slices stay byte-identical to the whole run.
#include "gl/pass_inputs.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace planet {

// Where the graph tells what became of each pass; GpuTimer is one.
class PassRecorder {
 public:
  virtual ~PassRecorder() = default;
  virtual void begin(const std::string& pass) = 0;
  virtual void end() = 0;
  // Its inputs had not changed: the last result still holds.
  virtual void reuse(const std::string& pass) = 0;
  // The frame did not need it.
  virtual void skip(const std::string& pass) = 0;
};

// Declared with designated initializers, naming only what it has:
// {.name = "sky", .reads = {"sky_view_lut"}, .run = ...}.
struct Pass {
  std::string name;
  // The passes whose results this one reads: run (or reused) before it.
  // A name not among the frame's passes is an error (std::logic_error).
  std::vector<std::string> reads = {};
  // Empty: the frame always needs it.
  std::function<bool()> needed = {};
  // Empty: it has no result to keep, and runs whenever it is needed.
  std::function<PassKey()> inputs = {};
  std::function<void()> run = {};
  // The pass times itself (it runs passes of its own, as the atmosphere's
  // technique does within the frame): the graph neither begins nor ends a
  // timing around it. Timer queries do not nest.
  bool times_itself = false;
};

class PassGraph {
 public:
  // Runs the passes in the order given, but each after every pass it reads
  // (std::logic_error for a cycle or an unknown name), as needed, reused
  // or run.
  void run(std::vector<Pass> passes, PassRecorder& recorder);
  // Every pass with inputs runs the next time it is needed, as on the first
  // frame (a technique whose settings ask for no reuse calls it each frame).
  void forget();
  // How many times the pass has run since the graph was made or forgot.
  uint64_t runs(const std::string& pass) const;

 private:
  PassInputs inputs_;
  std::map<std::string, uint64_t> runs_;
};

// The passes' order: each after the passes it reads, otherwise as given.
std::vector<size_t> pass_order(const std::vector<Pass>& passes);

}  // namespace planet
