#pragma once
// Ctrl-C (SIGINT) during a long job: while an InterruptScope lives, SIGINT
// sets a flag instead of ending the process. The job polls the flag,
// finishes what it must to leave whole files (a frame, a checkpoint),
// stops, and says how to go on; the program then exits with 130, as a
// shell reports a program stopped by SIGINT.
#include <atomic>

namespace planet {

class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  bool interrupted() const { return flag().load(); }
  // For jobs that poll it from worker threads.
  static const std::atomic<bool>& flag();

 private:
  void (*previous_)(int);
};

constexpr int kInterruptedExitStatus = 130;

}  // namespace planet
