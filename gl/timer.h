#pragma once
// GPU time per pass, from GL_TIME_ELAPSED queries. Results are read once a
// frame is finished, which waits for the GPU: fine for capture and
// benchmarks, where the numbers are the point.
#include "gl/pass_graph.h"

#include <epoxy/gl.h>

#include <chrono>
#include <string>
#include <vector>

namespace planet {

struct PassTiming {
  std::string pass;
  double gpu_ms = 0;
  // With a synchronous timer, the wall time from the GL's being idle before
  // the pass to its being idle after it; 0 otherwise. It counts what a
  // timer query may miss: on llvmpipe the vertex shaders and the binning
  // run in the calling thread, and its queries time the rasteriser alone.
  double wall_ms = 0;
  // The pass did not run: what it would have computed was still valid
  // from an earlier frame (its inputs had not changed), and was reused.
  bool reused = false;
  // The pass ran on the CPU: gpu_ms and wall_ms hold its wall time.
  bool on_cpu = false;
  // The frame did not need the pass: it did not run, and nothing of it
  // was shown.
  bool skipped = false;
  bool ran() const { return !reused && !skipped; }
};

class GpuTimer final : public PassRecorder {
 public:
  GpuTimer() = default;
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // Synchronous: each pass also waits for the GL before it begins and after
  // it ends, and its wall time is kept (PassTiming::wall_ms). For
  // benchmarks: the waits take from the frame what overlap would give.
  void set_synchronous(bool synchronous) { synchronous_ = synchronous; }
  // Queries do not nest: end one pass before beginning the next.
  void begin(const std::string& pass) override;
  void end() override;
  // Records a pass that did not run this frame because its last result
  // still held: it is listed, at 0 ms, with `reused` set.
  void reuse(const std::string& pass) override;
  // Records a pass the frame did not need: listed, at 0 ms, with `skipped`
  // set.
  void skip(const std::string& pass) override;
  // Records a pass that ran on the CPU, taking `ms` of wall time.
  void cpu(const std::string& pass, double ms);
  // Waits for every pending query and returns the frame's passes in order,
  // then starts over.
  std::vector<PassTiming> collect();

 private:
  struct Pending {
    std::string pass;
    GLuint query;
    std::chrono::steady_clock::time_point begun;
    double wall_ms = 0;
    bool reused = false;  // no query: the pass did not run
    bool on_cpu = false;  // no query: wall_ms is its time
    bool skipped = false;  // no query: the frame did not need it
  };
  bool synchronous_ = false;
  bool group_open_ = false;  // the pass's debug group, between begin() and end()
  std::vector<GLuint> free_;
  std::vector<Pending> pending_;
};

}  // namespace planet
