#pragma once
// Civil time for the simulation: UTC as seconds since J2000.0 (2000-01-01
// 12:00:00 UTC), parsed from and printed as ISO 8601, and the conversions
// the ephemerides need (Julian date, terrestrial time).
#include <string>

namespace planet {

// Seconds of UTC since 2000-01-01T12:00:00Z, leap seconds not counted (as
// POSIX time does), so that one day is always 86400 s.
using UtcSeconds = double;

// "2026-06-21T12:00:00Z", "2026-06-21T12:00:00.250Z", "2026-06-21T12:00Z"
// or "2026-06-21" (midnight). Throws InputError naming `what` (the field or
// option) when the text does not parse or a field is out of range.
UtcSeconds parse_utc(const std::string& text, const std::string& what);
// ISO 8601 with milliseconds: "2026-06-21T12:00:00.000Z".
std::string format_utc(UtcSeconds utc);

// Julian date of the UTC instant (UT1 is taken as UTC: |UT1 - UTC| < 0.9 s).
double julian_date(UtcSeconds utc);
// TT - UTC in seconds: 32.184 s plus the leap seconds (TAI - UTC) in force,
// from ERFA's copy of the IERS table (Bulletin C); 10 s before 1972.
double tt_minus_utc(UtcSeconds utc);

// The simulation's clock: a UTC epoch and the simulated seconds since it,
// kept apart so that a recorded flight reproduces the same instants.
class SimClock {
 public:
  explicit SimClock(UtcSeconds epoch = 0) : epoch_(epoch) {}
  UtcSeconds utc() const { return epoch_ + elapsed_; }
  UtcSeconds epoch() const { return epoch_; }
  double elapsed() const { return elapsed_; }
  // Simulated time passes `scale` times faster than real time; 0 pauses.
  double scale() const { return scale_; }
  void set_scale(double scale) { scale_ = scale; }
  void advance(double real_seconds) { elapsed_ += real_seconds * scale_; }
  void set(UtcSeconds utc) {
    epoch_ = utc;
    elapsed_ = 0;
  }
  // Starts a new epoch at the current instant rounded to the millisecond,
  // the precision at which format_utc writes it.
  void rebase_to_millisecond();

 private:
  UtcSeconds epoch_ = 0;
  double elapsed_ = 0;
  double scale_ = 1;
};

}  // namespace planet
