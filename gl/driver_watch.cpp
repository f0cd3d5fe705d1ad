#include "gl/driver_watch.h"

#include "core/error.h"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>

namespace planet {

namespace {

using Clock = std::chrono::steady_clock;

// Since when the outermost wait has blocked (Clock ticks; 0: none), and on what.
std::atomic<Clock::rep> g_waiting_since{0};
std::atomic<const char*> g_waiting_on{nullptr};
thread_local int t_depth = 0;

double read_timeout() {
  const char* env = std::getenv("PLANET_GL_TIMEOUT_S");
  if (!env || !*env) return 120.0;
  char* end = nullptr;
  double s = std::strtod(env, &end);
  if (end == env || *end != '\0' || !(s >= 0.0 && s <= 86400.0)) {
    throw InputError(fmt::format(
        "PLANET_GL_TIMEOUT_S='{}' is not a number of seconds from 0 (no watch) to 86400", env));
  }
  return s;
}

[[noreturn]] void give_up(double limit, const char* what) {
  // From the watch thread while the main thread is blocked: no locks, no
  // allocation, nothing that could wait on what is stuck.
  char line[512];
  int n = std::snprintf(line, sizeof line,
                        "planet: error: the GL driver has not answered for %.0f s while %s; "
                        "giving up (PLANET_GL_TIMEOUT_S sets the limit)\n",
                        limit, what ? what : "waiting for it");
  if (n > 0) {
    ssize_t ignored = write(STDERR_FILENO, line, size_t(std::min(n, int(sizeof line) - 1)));
    (void)ignored;
  }
  _exit(1);
}

void watch(double limit) {
  const auto step = std::chrono::duration<double>(std::clamp(limit / 20.0, 0.05, 1.0));
  while (true) {
    std::this_thread::sleep_for(step);
    Clock::rep since = g_waiting_since.load();
    if (since == 0) continue;
    double waited = std::chrono::duration<double>(Clock::now().time_since_epoch() -
                                                  Clock::duration(since))
                        .count();
    if (waited > limit) give_up(limit, g_waiting_on.load());
  }
}

void start_watch_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    double limit = driver_timeout_seconds();
    if (limit > 0) std::thread(watch, limit).detach();
  });
}

bool simulated_stall(const char* what) {
  static const char* pattern = std::getenv("PLANET_GL_SIMULATE_STALL");
  static std::atomic<bool> stalled{false};
  if (!pattern || !*pattern || !std::strstr(what, pattern)) return false;
  return !stalled.exchange(true);
}

}  // namespace

double driver_timeout_seconds() {
  static const double limit = read_timeout();
  return limit;
}

DriverWait::DriverWait(const char* what) {
  if (t_depth++ > 0) return;
  outermost_ = true;
  start_watch_once();
  g_waiting_on.store(what);
  g_waiting_since.store(std::max<Clock::rep>(Clock::now().time_since_epoch().count(), 1));
  if (simulated_stall(what)) {
    while (true) std::this_thread::sleep_for(std::chrono::hours(1));
  }
}

DriverWait::~DriverWait() {
  --t_depth;
  if (outermost_) g_waiting_since.store(0);
}

}  // namespace planet
