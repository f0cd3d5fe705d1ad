#include "core/parallel.h"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace planet {

int thread_count(int requested) {
  if (requested > 0) return requested;
  // The cores this process may run on, not the machine's: a scheduler
  // (Slurm's task/affinity, a container's cpuset) binds a task to a few of
  // a large node's cores, and a thread per core of the node would crowd them.
  cpu_set_t cores;
  CPU_ZERO(&cores);
  if (sched_getaffinity(0, sizeof cores, &cores) == 0 && CPU_COUNT(&cores) > 0) {
    return CPU_COUNT(&cores);
  }
  return std::max(1, int(std::thread::hardware_concurrency()));
}

void parallel_for(int count, int threads, const std::function<void(int)>& work,
                  const std::function<void(int)>& on_progress) {
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        work(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
        next = count;  // hand out no more
      }
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < thread_count(threads); ++i) pool.emplace_back(worker);
  if (on_progress) {
    while (done.load() < count && !failed.load()) {
      on_progress(done.load());
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
  }
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace planet
