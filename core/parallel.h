#pragma once
// Work spread over the cores: items [0, count) handed out in order to a pool
// of threads, each item done by exactly one of them, so that a result that
// depends only on its item (a row of pixels with their own random streams)
// has the same bits at any thread count.
#include <functional>

namespace planet {

// Threads to use: `requested`, or, when it is 0 or below, every core this
// process may run on (its CPU affinity).
int thread_count(int requested);

// Calls work(i) for every i in [0, count) on thread_count(threads) threads
// and returns when all are done. While they run, the calling thread calls
// on_progress(items done) every 250 ms (if given). An exception thrown by
// work ends the remaining items and is rethrown here.
void parallel_for(int count, int threads, const std::function<void(int)>& work,
                  const std::function<void(int)>& on_progress = {});

}  // namespace planet
