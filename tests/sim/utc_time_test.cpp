#include "sim/utc_time.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(UtcTimeTest, J2000IsZeroAndJulianDateMatches) {
  EXPECT_DOUBLE_EQ(parse_utc("2000-01-01T12:00:00Z", "t"), 0.0);
  // Meeus 1998, example 7.a: 1957 October 4.81 is JD 2436116.31.
  UtcSeconds sputnik = parse_utc("1957-10-04T19:26:24Z", "t");
  EXPECT_NEAR(julian_date(sputnik), 2436116.31, 1e-9);
  EXPECT_DOUBLE_EQ(parse_utc("2026-06-21", "t"), parse_utc("2026-06-21T00:00:00Z", "t"));
  EXPECT_DOUBLE_EQ(parse_utc("2026-06-21T12:30Z", "t") + 15.25,
                   parse_utc("2026-06-21T12:30:15.25Z", "t"));
}

TEST(UtcTimeTest, FormatRoundTrips) {
  for (const char* text : {"2026-06-21T12:00:00.000Z", "1950-01-01T00:00:00.000Z",
                           "2049-12-31T23:59:59.999Z", "2024-02-29T06:07:08.123Z"}) {
    EXPECT_EQ(format_utc(parse_utc(text, "t")), text);
  }
}

TEST(UtcTimeTest, MalformedTimesAreInputErrorsNamingTheField) {
  for (const char* text :
       {"", "2026-13-01T00:00:00Z", "2026-02-29T00:00:00Z", "2026-06-21T25:00:00Z",
        "2026-06-21T12:00:00", "noon", "2026-06-21T12:00:61Z", "2026/06/21"}) {
    try {
      parse_utc(text, "--time");
      ADD_FAILURE() << "no error for '" << text << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--time"), std::string::npos) << e.what();
    }
  }
}

TEST(UtcTimeTest, LeapSecondsFollowTheIersTable) {
  EXPECT_DOUBLE_EQ(tt_minus_utc(parse_utc("2016-12-31T23:59:59Z", "t")), 32.184 + 36);
  EXPECT_DOUBLE_EQ(tt_minus_utc(parse_utc("2017-01-01T00:00:00Z", "t")), 32.184 + 37);
  EXPECT_DOUBLE_EQ(tt_minus_utc(parse_utc("1980-06-01T00:00:00Z", "t")), 32.184 + 19);
}

TEST(UtcTimeTest, ClockScalesAndPauses) {
  SimClock clock(100.0);
  clock.set_scale(1000.0);
  clock.advance(0.5);
  EXPECT_DOUBLE_EQ(clock.utc(), 600.0);
  clock.set_scale(0.0);
  clock.advance(10.0);
  EXPECT_DOUBLE_EQ(clock.utc(), 600.0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
