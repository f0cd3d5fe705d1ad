// A switch of body keeps the place, the height above the ground and the
// local solar time (issue 62, points 1 and 2): B from the Alps at 10:30
// local time had put the camera 1/1000 of a radius up in the Martian night
// (sun -41.1 deg) and in the lunar night (sun -4.0 deg).
#include "sim/body_switch.h"
#include "sim/free_flight.h"
#include "sim/sun_ephemeris.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

struct Flying {
  Body body;
  Camera camera;
  UtcSeconds utc;
};

// fly's default start: the Alps, 2 m up, looking east at 10:00 UTC.
Flying alps() {
  Body earth = load_body(find_body_file("earth"));
  Geodesy geodesy(earth.shape);
  Camera camera = geodesy.camera_at(Geodetic{glm::radians(46.55), glm::radians(7.98), 923.4},
                                    glm::radians(90.0), glm::radians(-10.0), glm::radians(60.0));
  return {earth, camera, parse_utc("2026-06-21T10:00:00Z", "t")};
}

double sun_elevation(const Body& body, const Geodetic& place, UtcSeconds utc) {
  return horizon_angles(sun_dir_body(body.ephemeris, body.rotation, utc), place.lat, place.lon)
      .elevation;
}

TEST(BodySwitchTest, KeepsLatitudeLongitudeHeightAboveTheGroundAndLook) {
  Flying from = alps();
  Body mars = load_body(find_body_file("mars"));
  BodySwitch s = switch_body(from.body, from.camera, 2.0, from.utc, mars,
                             [](const Geodetic&) { return 289.2; });
  EXPECT_NEAR(glm::degrees(s.place.lat), 46.55, 1e-9);
  EXPECT_NEAR(glm::degrees(s.place.lon), 7.98, 1e-9);
  EXPECT_NEAR(s.height_above_ground, 2.0, 1e-12);
  EXPECT_FALSE(s.height_clamped);
  EXPECT_NEAR(s.place.height, 291.2, 1e-9);
  Geodesy geodesy(mars.shape);
  Geodetic at = geodesy.geodetic_from_body(s.camera.pos_body);
  EXPECT_NEAR(at.height, 291.2, 1e-6);
  LookAngles look = look_angles(glm::conjugate(glm::quat_cast(geodesy.body_from_enu(at))) *
                                s.camera.body_from_camera);
  EXPECT_NEAR(glm::degrees(look.heading), 90.0, 1e-6);
  EXPECT_NEAR(glm::degrees(look.pitch), -10.0, 1e-6);
  EXPECT_NEAR(glm::degrees(look.roll), 0.0, 1e-6);
}

TEST(BodySwitchTest, ClampsTheHeightToWhatTheNewBodyAllows) {
  Flying from = alps();
  Body asteroid = load_body(find_body_file("asteroid"));
  auto ground = [](const Geodetic&) { return -307.2; };
  // 400 km over the Earth would be 13 radii over a 30 km asteroid.
  BodySwitch high = switch_body(from.body, from.camera, 400e3, from.utc, asteroid, ground);
  EXPECT_TRUE(high.height_clamped);
  EXPECT_NEAR(high.height_above_ground, 30e3, 1e-9);
  EXPECT_NEAR(high.place.height, 30e3 - 307.2, 1e-9);
  BodySwitch low = switch_body(from.body, from.camera, 0.1, from.utc, asteroid, ground);
  EXPECT_TRUE(low.height_clamped);
  EXPECT_NEAR(low.height_above_ground, FreeFlight::kClearance, 1e-12);
}

TEST(BodySwitchTest, KeepsTheLocalSolarTimeSoThatAMorningStaysDay) {
  Flying from = alps();
  Geodetic place{glm::radians(46.55), glm::radians(7.98), 0.0};
  double hour_angle =
      sun_hour_angle(sun_dir_body(from.body.ephemeris, from.body.rotation, from.utc), place.lon);
  // 10:00 UTC at 7.98 E: 10:32 of mean time, less the equation of time.
  EXPECT_NEAR(local_solar_hours(hour_angle), 10.5, 0.05);
  for (const char* name : {"mars", "moon", "asteroid", "earth"}) {
    Body to = load_body(find_body_file(name));
    BodySwitch s =
        switch_body(from.body, from.camera, 2.0, from.utc, to, [](const Geodetic&) { return 0.0; });
    double kept = sun_hour_angle(sun_dir_body(to.ephemeris, to.rotation, s.utc), place.lon);
    EXPECT_NEAR(std::remainder(kept - hour_angle, 2 * glm::pi<double>()), 0.0, 1e-5) << name;
    EXPECT_NEAR(s.sun_hour_angle, hour_angle, 1e-12) << name;
    // Within half a solar day (the Moon's is 29.5 Earth days).
    EXPECT_LE(std::abs(s.utc - from.utc), 0.5 * 29.6 * 86400.0) << name;
    double elevation = glm::degrees(sun_elevation(to, place, s.utc));
    std::printf("%s: local solar time %.2f h, sun %.1f deg, clock moved %.0f s\n", name,
                local_solar_hours(kept), elevation, s.utc - from.utc);
    // The same UTC instant had the sun at -41.1 deg on Mars and -4.0 on the
    // Moon; at 10:30 it stands 19.8 deg high in the Martian winter and
    // 39.4 on the Moon. (The asteroid's pole leans 42 deg: its seasons are
    // its own.)
    if (std::string(name) != "asteroid") {
      EXPECT_GT(elevation, 15.0) << name;
    }
  }
  // Back on Earth at once: the same instant.
  BodySwitch back = switch_body(from.body, from.camera, 2.0, from.utc, from.body,
                                [](const Geodetic&) { return 0.0; });
  EXPECT_NEAR(back.utc, from.utc, 1.0);
}

TEST(BodySwitchTest, DaylightSaysDayTwilightOrNight) {
  EXPECT_EQ(daylight(glm::radians(35.0), true), Daylight::kDay);
  EXPECT_EQ(daylight(glm::radians(-5.0), true), Daylight::kTwilight);
  EXPECT_EQ(daylight(glm::radians(-41.1), true), Daylight::kNight);
  // No air, no twilight: the Moon's -4.0 deg is night.
  EXPECT_EQ(daylight(glm::radians(-4.0), false), Daylight::kNight);
  EXPECT_STREQ(daylight_name(Daylight::kNight), "night");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
