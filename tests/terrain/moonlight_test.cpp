// The Moon as a light (terrain/moonlight.h): its phase from where the Sun,
// the Moon and the observer stand, and its light as the disk's brightness
// times the inverse squares of the two distances.
#include "terrain/moonlight.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMoonRadius = 1737.4e3;
constexpr double kMoonDistance = 384400e3, kAu = 149597870700.0;

Regolith average_moon() { return Regolith{0.21, -0.26, 1.0, 0.07, 20.0 * kPi / 180.0, ""}; }

TEST(MoonlightTest, FullMoonIsTheGeometricAlbedoTimesTheInverseSquares) {
  // The Sun behind the observer, the three in a line: phase 0.
  const glm::dvec3 sun(-kAu, 0, 0), observer(0.0), moon(kMoonDistance, 0, 0);
  const Moonlight m = moonlight(average_moon(), kMoonRadius, sun, moon, observer);
  EXPECT_NEAR(m.phase, 0.0, 1e-9);
  EXPECT_NEAR(m.illuminated_fraction, 1.0, 1e-12);
  EXPECT_NEAR(m.disk_brightness, regolith_disk_brightness(average_moon(), 0.0), 1e-12);
  const double expected = m.disk_brightness * std::pow(kMoonRadius / kMoonDistance, 2) *
                          std::pow(kAu / (kAu + kMoonDistance), 2);
  EXPECT_NEAR(m.over_sunlight / expected, 1.0, 1e-12);
  // About 2.5e-6 of the sunlight: the full Moon's 0.3 lux against the
  // sun's 130 000 lux.
  EXPECT_GT(m.over_sunlight, 2.0e-6);
  EXPECT_LT(m.over_sunlight, 3.0e-6);
}

TEST(MoonlightTest, QuarterMoonIsHalfLitAndFarDimmer) {
  // The Sun off to the side of the Earth-Moon line, far away: phase 90 deg.
  const glm::dvec3 observer(0.0), moon(kMoonDistance, 0, 0);
  const glm::dvec3 sun = moon + glm::dvec3(0, kAu, 0);
  const Moonlight quarter = moonlight(average_moon(), kMoonRadius, sun, moon, observer);
  EXPECT_NEAR(quarter.phase, kPi / 2, 1e-9);
  EXPECT_NEAR(quarter.illuminated_fraction, 0.5, 1e-9);
  const Moonlight full =
      moonlight(average_moon(), kMoonRadius, -glm::dvec3(kAu, 0, 0), moon, observer);
  // Half the disk lit, but a quarter Moon sends about a tenth of the full
  // Moon's light (Lane and Irvine 1973: 2.5 mag from 0 to 90 deg).
  const double ratio = quarter.over_sunlight / full.over_sunlight;
  EXPECT_GT(ratio, 0.06);
  EXPECT_LT(ratio, 0.14);
}

TEST(MoonlightTest, TheLightFallsAsTheInverseSquareOfTheDistance) {
  const glm::dvec3 sun(-kAu, 0, 0), moon(kMoonDistance, 0, 0);
  const Moonlight near = moonlight(average_moon(), kMoonRadius, sun, moon, glm::dvec3(0.0));
  const Moonlight far =
      moonlight(average_moon(), kMoonRadius, sun, moon, glm::dvec3(-kMoonDistance, 0, 0));
  // The observer twice as far from the Moon (and a little farther from
  // the Sun, which the sunlight it is measured against takes too).
  const double sun_ratio = std::pow((kAu - kMoonDistance) / kAu, 2);
  EXPECT_NEAR(far.over_sunlight / near.over_sunlight, 0.25 * sun_ratio, 1e-9);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
