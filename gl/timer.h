#pragma once
// GPU time per pass, from GL_TIME_ELAPSED queries. Results are read once a
// frame is finished, which waits for the GPU: fine for capture and
// benchmarks, where the numbers are the point.
#include <epoxy/gl.h>

#include <chrono>
#include <string>
#include <vector>

namespace planet {

struct PassTiming {
  std::string pass;
  double gpu_ms = 0;
};

class GpuTimer {
 public:
  GpuTimer() = default;
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // Queries do not nest: end one pass before beginning the next.
  void begin(const std::string& pass);
  void end();
  // Waits for every pending query and returns the frame's passes in order,
  // then starts over.
  std::vector<PassTiming> collect();

 private:
  struct Pending {
    std::string pass;
    GLuint query;
    std::chrono::steady_clock::time_point begun;
  };
  std::vector<GLuint> free_;
  std::vector<Pending> pending_;
};

}  // namespace planet
