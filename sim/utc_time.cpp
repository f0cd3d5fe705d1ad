#include "sim/utc_time.h"

#include "core/error.h"

#include <erfa.h>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace planet {

namespace {

constexpr double kSecondsPerDay = 86400.0;
// Days from 1970-01-01 to 2000-01-01, and J2000.0 is noon of that day.
constexpr double kJ2000FromUnixSeconds = 10957.0 * kSecondsPerDay + 43200.0;

// Days since 1970-01-01 of a proleptic Gregorian date (Hinnant,
// "chrono-Compatible Low-Level Date Algorithms", days_from_civil).
long days_from_civil(long y, long m, long d) {
  y -= m <= 2;
  const long era = (y >= 0 ? y : y - 399) / 400;
  const long yoe = y - era * 400;
  const long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

// The inverse, same source (civil_from_days).
void civil_from_days(long z, long& y, long& m, long& d) {
  z += 719468;
  const long era = (z >= 0 ? z : z - 146096) / 146097;
  const long doe = z - era * 146097;
  const long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const long mp = (5 * doy + 2) / 153;
  d = doy - (153 * mp + 2) / 5 + 1;
  m = mp < 10 ? mp + 3 : mp - 9;
  y = yoe + era * 400 + (m <= 2);
}

bool leap_year(long y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

}  // namespace

UtcSeconds parse_utc(const std::string& text, const std::string& what) {
  auto fail = [&](const std::string& reason) -> UtcSeconds {
    throw InputError(
        fmt::format("{}: '{}' {} (expected UTC as YYYY-MM-DDTHH:MM:SSZ)", what, text, reason));
  };
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, n = 0;
  double s = 0;
  size_t len = text.size();
  if (std::sscanf(text.c_str(), "%4d-%2d-%2d%n", &y, &mo, &d, &n) != 3 || n != 10) {
    return fail("is not a date");
  }
  if (len > 10) {
    int n2 = 0;
    if (text[10] != 'T' && text[10] != ' ') return fail("has no 'T' between date and time");
    if (std::sscanf(text.c_str() + 11, "%2d:%2d%n", &h, &mi, &n2) != 2 || n2 != 5) {
      return fail("has no time HH:MM");
    }
    size_t at = 16;
    if (at < len && text[at] == ':') {
      int n3 = 0;
      if (std::sscanf(text.c_str() + at + 1, "%lf%n", &s, &n3) != 1 || n3 < 2 ||
          !std::isdigit(static_cast<unsigned char>(text[at + 1])) ||
          !std::isdigit(static_cast<unsigned char>(text[at + 2]))) {
        return fail("has no seconds SS after the minutes");
      }
      at += 1 + size_t(n3);
    }
    if (at != len - 1 || text[at] != 'Z') return fail("does not end in Z (UTC)");
  }
  static constexpr std::array<int, 12> kDays = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (mo < 1 || mo > 12) return fail("has no month " + std::to_string(mo));
  int month_days = kDays[size_t(mo - 1)] + (mo == 2 && leap_year(y) ? 1 : 0);
  if (d < 1 || d > month_days) return fail("has no such day of the month");
  if (h > 23 || mi > 59 || !(s >= 0.0 && s < 60.0)) return fail("has a time out of range");
  double days = double(days_from_civil(y, mo, d));
  return days * kSecondsPerDay + h * 3600.0 + mi * 60.0 + s - kJ2000FromUnixSeconds;
}

std::string format_utc(UtcSeconds utc) {
  double unix_ms = std::round((utc + kJ2000FromUnixSeconds) * 1000.0);
  double day = std::floor(unix_ms / (kSecondsPerDay * 1000.0));
  long ms_of_day = long(unix_ms - day * kSecondsPerDay * 1000.0);
  long y, m, d;
  civil_from_days(long(day), y, m, d);
  return fmt::format("{:04d}-{:02d}-{:02d}T{:02d}:{:02d}:{:02d}.{:03d}Z", y, m, d,
                     ms_of_day / 3600000, (ms_of_day / 60000) % 60, (ms_of_day / 1000) % 60,
                     ms_of_day % 1000);
}

double julian_date(UtcSeconds utc) { return 2451545.0 + utc / kSecondsPerDay; }

double tt_minus_utc(UtcSeconds utc) {
  // TAI - UTC from ERFA's copy of the IERS table (Bulletin C): 10 s in 1972
  // to 37 s from 2017-01-01, no leap second announced since. Before 1972
  // UTC's rate was not the SI second's; 10 s serves there.
  int year = 0, month = 0, day = 0;
  double fraction = 0, tai_minus_utc = 10.0;
  if (eraJd2cal(2451545.0, utc / kSecondsPerDay, &year, &month, &day, &fraction) == 0 &&
      year >= 1972) {
    // A status of 1 only says the table may be out of date for that year.
    if (eraDat(year, month, day, fraction, &tai_minus_utc) < 0) tai_minus_utc = 37.0;
  }
  return 32.184 + tai_minus_utc;
}

void SimClock::rebase_to_millisecond() {
  // Through the text, so that a script that reads the epoch back gets the
  // very same double.
  set(parse_utc(format_utc(utc()), "clock"));
}

}  // namespace planet
