// Regolith's law against published measures: the Moon's phase curve (its
// disk-integrated brightness against phase angle) and geometric albedo,
// Eros's geometric albedo, a full disk that stays bright to its limb, and
// Lambert's law wherever a body's file names no regolith.
#include "terrain/regolith.h"

#include "core/data_paths.h"
#include "core/error.h"
#include "sim/body.h"
#include "terrain/terrain_config.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Regolith regolith_of(const char* body_file) {
  TerrainConfig config = parse_terrain(load_body(data_dir() / "planets" / body_file));
  EXPECT_TRUE(config.regolith.has_value()) << body_file;
  return config.regolith.value_or(Regolith{});
}

// Lane and Irvine 1973, as Allen's Astrophysical Quantities (4th ed.,
// section 12.4) gives it: V(alpha) - V(0) = 0.026 |alpha| + 4.0e-9 alpha^4,
// alpha in degrees; a fit over phase angles from a few degrees to past
// 120, its V(0) the linear law's, not the opposition peak's.
double lane_irvine_mag(double alpha_deg) {
  return 0.026 * alpha_deg + 4.0e-9 * std::pow(alpha_deg, 4);
}

// A Lambertian sphere's phase function (Russell 1916): (sin a + (pi - a) cos a) / pi.
double lambert_sphere(double alpha) {
  return (std::sin(alpha) + (3.14159265358979323846 - alpha) * std::cos(alpha)) /
         3.14159265358979323846;
}

TEST(RegolithTest, TheMoonsPhaseCurveFollowsTheMeasuredOne) {
  const Regolith moon = regolith_of("moon.json");
  // Both curves from 5 degrees, where the published law takes over from
  // the opposition peak it leaves out (0.26 mag in the model's from 0 to 5).
  const double model_5 = regolith_disk_brightness(moon, 5 * kDeg);
  const double lambert_5 = lambert_sphere(5 * kDeg);
  std::printf("phase  model  Lane&Irvine  model-L&I  Lambert-L&I   (mag, from 5 deg)\n");
  struct Row {
    double alpha_deg, tolerance_mag;
  };
  // 0.10 mag to 60 deg; beyond, Hapke's law with these parameters falls
  // faster than the measured Moon (0.19 mag at 90, 0.33 at 120).
  for (Row row : {Row{0, 0.15}, Row{10, 0.1}, Row{20, 0.1}, Row{30, 0.1}, Row{45, 0.1},
                  Row{60, 0.1}, Row{90, 0.25}, Row{120, 0.4}}) {
    double model =
        -2.5 * std::log10(regolith_disk_brightness(moon, row.alpha_deg * kDeg) / model_5);
    double lambert = -2.5 * std::log10(lambert_sphere(row.alpha_deg * kDeg) / lambert_5);
    double published = lane_irvine_mag(row.alpha_deg) - lane_irvine_mag(5);
    std::printf("%5.0f  %5.3f  %11.3f  %+9.3f  %+11.3f\n", row.alpha_deg, model, published,
                model - published, lambert - published);
    if (row.alpha_deg > 0) {
      EXPECT_NEAR(model, published, row.tolerance_mag) << row.alpha_deg;
    }
  }
  // Lambert's sphere misses the measured curve by a magnitude at 90 deg.
  EXPECT_GT(std::abs(-2.5 * std::log10(lambert_sphere(90 * kDeg) / lambert_5) -
                     (lane_irvine_mag(90) - lane_irvine_mag(5))),
            1.0);
}

TEST(RegolithTest, GeometricAlbedosMatchThePublishedOnes) {
  // The brightness at phase 0 over that of a white Lambertian disk of the
  // same size is the geometric albedo: the Moon's 0.12 in V (Allen's
  // Astrophysical Quantities), Eros's 0.23 at 550 nm (Li et al. 2004).
  const double moon = regolith_disk_brightness(regolith_of("moon.json"), 0.0);
  const double eros = regolith_disk_brightness(regolith_of("eros.json"), 0.0);
  std::printf("geometric albedo: Moon %.4f (0.12), Eros %.4f (0.23)\n", moon, eros);
  EXPECT_NEAR(moon, 0.12, 0.015);
  EXPECT_NEAR(eros, 0.23, 0.02);
}

TEST(RegolithTest, TheFullMoonIsFlatToItsLimb) {
  // At phase 0 a point at angle t from the disk's centre is lit and seen at
  // t: Lambert's radiance falls as cos t; regolith's stays near its centre's.
  const Regolith moon = regolith_of("moon.json");
  const double centre = regolith_reflectance(moon, 1.0, 1.0, 1.0);
  for (double t_deg : {30.0, 60.0, 80.0, 85.0}) {
    double mu = std::cos(t_deg * kDeg);
    double ratio = regolith_reflectance(moon, mu, mu, 1.0) / centre;
    std::printf("full disk at %2.0f deg from its centre: %.3f of the centre (Lambert %.3f)\n",
                t_deg, ratio, mu);
    EXPECT_GT(ratio, 0.9);
  }
}

TEST(RegolithTest, TheTerminatorIsSharperThanLambertsAndTheSunBelowGivesNothing) {
  // Seen from straight up, the sun 5 deg over the horizon: the rough
  // surface's own shadows take more than Lambert's cosine would.
  const Regolith moon = regolith_of("moon.json");
  const double mu0_high = std::cos(30 * kDeg), mu0_low = std::cos(85 * kDeg);
  const double high = regolith_reflectance(moon, mu0_high, 1.0, mu0_high);
  const double low = regolith_reflectance(moon, mu0_low, 1.0, mu0_low);
  std::printf("sun 5 deg up against 60 deg up: %.3f (Lambert %.3f)\n", low / high,
              mu0_low / mu0_high);
  EXPECT_LT(low / high, mu0_low / mu0_high);
  EXPECT_EQ(regolith_reflectance(moon, -0.01, 1.0, 0.0), 0.0);
  EXPECT_EQ(regolith_reflectance(moon, 0.0, 0.5, 0.2), 0.0);
}

TEST(RegolithTest, BodiesWithoutTheKeyStayLambertian) {
  for (const char* body : {"earth.json", "mars.json"}) {
    EXPECT_FALSE(parse_terrain(load_body(data_dir() / "planets" / body)).regolith) << body;
  }
  for (const char* body : {"moon.json", "eros.json", "asteroid.json"}) {
    TerrainConfig config = parse_terrain(load_body(data_dir() / "planets" / body));
    ASSERT_TRUE(config.regolith) << body;
    EXPECT_FALSE(config.regolith->source.empty()) << body;
  }
}

TEST(RegolithTest, BadParametersNameTheFileAndTheField) {
  Body moon = load_body(data_dir() / "planets" / "moon.json");
  moon.terrain["regolith"]["w"] = 1.5;
  try {
    parse_terrain(moon);
    FAIL() << "a single-scattering albedo of 1.5 was taken";
  } catch (const InputError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("moon.json"), std::string::npos) << what;
    EXPECT_NE(what.find("regolith"), std::string::npos) << what;
    EXPECT_NE(what.find("w"), std::string::npos) << what;
  }
  moon = load_body(data_dir() / "planets" / "moon.json");
  moon.terrain["regolith"].erase("source");
  EXPECT_THROW(parse_terrain(moon), InputError);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
