#pragma once
// The passes of many frames, summed pass by pass: how often each ran and
// was reused, and its mean time over the frames it ran. What `fly` prints
// when it closes, beside its frame rate.
#include "gl/timer.h"

#include <map>
#include <string>
#include <vector>

namespace planet {

class PassTally {
 public:
  struct Pass {
    int ran = 0, reused = 0, skipped = 0;
    double gpu_ms = 0;   // summed over the frames it ran
    double wall_ms = 0;  // the same, where the timer was synchronous
  };

  void add(const std::vector<PassTiming>& frame);
  int frames() const { return frames_; }
  const std::map<std::string, Pass>& passes() const { return passes_; }
  // One line a pass, the costliest first: "  sky  12.34 ms  ran 40 of 50,
  // reused 10, skipped 2". The mean is over the frames the pass ran: its wall time
  // where the timer was synchronous, else its timer queries' GPU time.
  std::string summary() const;
  // The same passes as a table under a header, the costliest first (by
  // wall time where the timer was synchronous): each pass's mean wall and
  // GPU time over the frames it ran ("-" for a wall time not kept), and
  // how often it ran, was reused and skipped; then the frame's mean, its
  // passes' summed over all frames: what `--pass-table` prints.
  std::string table() const;

 private:
  int frames_ = 0;
  std::map<std::string, Pass> passes_;
};

}  // namespace planet
