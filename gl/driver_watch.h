#pragma once
// The program never waits for the GL driver for ever. Each place where the
// CPU blocks until the driver answers (a read back, a finish, a query's
// result, a swap) holds a DriverWait for as long as it blocks; a watch
// thread ends the program if one lasts longer than the limit: one line on
// stderr naming what was waited for and for how long, exit status 1. A call
// blocked in a driver cannot be cancelled, so that is the only way out;
// whatever was being written was under a temporary name and stays there,
// to be removed by the next run (core/atomic_file.h).
//
// The limit is PLANET_GL_TIMEOUT_S seconds (default 120: the longest single
// wait measured, a 1280x720 march on llvmpipe, is a few seconds; 0 turns the
// watch off). PLANET_GL_SIMULATE_STALL=TEXT makes the first wait whose name
// holds TEXT block for ever, as a driver that stopped would: the fault the
// tests end the program with.
#include <string>

namespace planet {

class DriverWait {
 public:
  // `what`: what the driver is being waited for ("reading the frame's
  // image back"); a literal, kept by pointer.
  explicit DriverWait(const char* what);
  ~DriverWait();
  DriverWait(const DriverWait&) = delete;
  DriverWait& operator=(const DriverWait&) = delete;

 private:
  bool outermost_ = false;
};

// The limit in seconds; 0 when the watch is off. Reads PLANET_GL_TIMEOUT_S
// once; a value that is not a number from 0 to 86400 is an InputError.
double driver_timeout_seconds();

}  // namespace planet
