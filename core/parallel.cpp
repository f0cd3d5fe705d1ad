#include "core/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace planet {

int thread_count(int requested) {
  return requested > 0 ? requested : std::max(1, int(std::thread::hardware_concurrency()));
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
