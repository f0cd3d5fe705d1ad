// Craters mark the ground they dig: dark floors, bright rims and the rayed
// ejecta of the young ones, where the heights put the craters, and only
// where the samples can carry them.
#include "terrain/procedural_height.h"

#include "core/data_paths.h"
#include "sim/body.h"
#include "terrain/surface_color.h"
#include "terrain/terrain_config.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// One octave of craters in cells of 10 km, depth a tenth of the radius,
// in three cells of ten: few overlap.
ProceduralHeight lone_craters() {
  NoiseLayer craters;
  craters.kind = NoiseLayer::Kind::kCraters;
  craters.amplitude = 1000.0;
  craters.wavelength = 10e3;
  craters.octaves = 1;
  craters.density = 0.3;
  craters.seed = 5;
  return ProceduralHeight(1e6, {craters}, 0.0, std::nullopt);
}

// Directions within `extent` metres of one place on a sphere of `radius`.
std::vector<glm::dvec3> directions(double radius, double extent, int count) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  const glm::dvec3 centre = radius * glm::normalize(glm::dvec3(0.2, -0.5, 0.6));
  std::vector<glm::dvec3> out;
  for (int i = 0; i < count; ++i) {
    out.push_back(
        glm::normalize(centre + extent * glm::dvec3(uniform(rng), uniform(rng), uniform(rng))));
  }
  return out;
}

TEST(CraterMarksTest, FloorsLieInTheBowlsRimsOnTheCrestsAndNothingBeyond) {
  const ProceduralHeight heights = lone_craters();
  int floors = 0, floors_below = 0, rims = 0, rims_above = 0, plain = 0, ejecta = 0;
  for (const glm::dvec3& d : directions(1e6, 200e3, 100000)) {
    CraterMarks m = heights.crater_marks(d, 10.0);
    double h = heights.height(d);
    if (m.floor > 0.99) {
      ++floors;
      floors_below += h < 0.0;
    }
    if (m.rim > 0.5) {
      ++rims;
      rims_above += h > 0.0;
    }
    if (m.ejecta > 0.0) ++ejecta;
    if (h == 0.0) {
      // Beyond the reach of every crater: no mark.
      ++plain;
      EXPECT_EQ(m.floor, 0.0);
      EXPECT_EQ(m.rim, 0.0);
      EXPECT_EQ(m.ejecta, 0.0);
    }
  }
  std::printf(
      "of 100000 points: %d on floors (%d below the plain), %d on rims (%d above), "
      "%d on ejecta, %d on the plain\n",
      floors, floors_below, rims, rims_above, ejecta, plain);
  ASSERT_GT(floors, 100);
  ASSERT_GT(rims, 200);
  ASSERT_GT(plain, 50000);
  EXPECT_GT(ejecta, 1000);
  // Where another crater's rim or bowl overlaps, a point can be both.
  EXPECT_GE(floors_below, 0.98 * floors);
  EXPECT_GE(rims_above, 0.95 * rims);
}

TEST(CraterMarksTest, NoCraterTooNarrowForTheSamplesMarksThem) {
  const ProceduralHeight heights = lone_craters();
  // The widest crater's radius is a quarter of the 10 km cell: no mark on
  // samples 2 km apart, the rims gone already at 1 km.
  for (const glm::dvec3& d : directions(1e6, 200e3, 5000)) {
    CraterMarks coarse = heights.crater_marks(d, 2000.0);
    EXPECT_EQ(coarse.floor + coarse.rim + coarse.ejecta, 0.0);
    EXPECT_EQ(heights.crater_marks(d, 1000.0).rim, 0.0);
  }
}

TEST(CraterMarksTest, YoungEjectaAreStreakedIntoRays) {
  // Around a crater whose ejecta show, on the ring where they are
  // brightest, the streaks make the brightest azimuth twice the dimmest.
  const ProceduralHeight heights = lone_craters();
  glm::dvec3 best{};
  double strongest = 0.0;
  for (const glm::dvec3& d : directions(1e6, 200e3, 40000)) {
    double e = heights.crater_marks(d, 10.0).ejecta;
    if (e > strongest) strongest = e, best = d;
  }
  ASSERT_GT(strongest, 0.5);
  // The crater's centre: the lowest point within 8 km of the brightest.
  glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), best));
  glm::dvec3 north = glm::cross(best, east);
  glm::dvec3 centre = best;
  double lowest = 1e300;
  for (int j = -80; j <= 80; ++j) {
    for (int i = -80; i <= 80; ++i) {
      glm::dvec3 d = glm::normalize(best + (100.0 * i * east + 100.0 * j * north) / 1e6);
      double h = heights.height(d);
      if (h < lowest) lowest = h, centre = d;
    }
  }
  // On the circle about it where the ejecta are brightest on average.
  auto on_circle = [&](double rho, int k) {
    double a = k * 3.14159265358979 / 180.0;
    return heights
        .crater_marks(
            glm::normalize(centre + rho * (std::cos(a) * east + std::sin(a) * north) / 1e6), 10.0)
        .ejecta;
  };
  double radius = 0.0, best_mean = 0.0;
  for (double rho = 500.0; rho <= 8000.0; rho += 250.0) {
    double mean = 0.0;
    for (int k = 0; k < 360; ++k) mean += on_circle(rho, k) / 360.0;
    if (mean > best_mean) best_mean = mean, radius = rho;
  }
  double dimmest = 1e300, brightest = 0.0;
  for (int k = 0; k < 360; ++k) {
    double e = on_circle(radius, k);
    dimmest = std::min(dimmest, e);
    brightest = std::max(brightest, e);
  }
  std::printf("ejecta %.0f m from a crater's centre: from %.3f to %.3f\n", radius, dimmest,
              brightest);
  EXPECT_GT(brightest, 2.0 * dimmest);
}

TEST(CraterMarksTest, MarsFloorsAreDarkerAndRimsBrighterThanThePlain) {
  Body mars = load_body(data_dir() / "planets" / "mars.json");
  const SurfacePalette& palette = parse_terrain(mars).palette;
  EXPECT_LT(crater_albedo(palette.craters, {1.0, 0.0, 0.0}), 0.8);
  EXPECT_GT(crater_albedo(palette.craters, {0.0, 1.0, 0.0}), 1.2);
  EXPECT_GT(crater_albedo(palette.craters, {0.0, 0.0, 1.0}), 1.3);
  EXPECT_EQ(crater_albedo(palette.craters, {}), 1.0);
}

TEST(CraterMarksTest, CratersLieWhereEveryCompilerPutsThem) {
  // Mars's heights at four places, as the shipped captures have them: a
  // crater's centre and radius are drawn in one order by every compiler
  // (they once came from one expression, whose arguments GCC and Clang
  // evaluate in opposite orders). The procedural Mars, whose craters they are.
  Body mars = load_body(project_root() / "tests/data/planets/mars_procedural.json");
  const TerrainConfig config = parse_terrain(mars);
  // Four places on the floors of the craters of 0.6-3 km radius.
  const glm::dvec3 at[4] = {{0.043316143479675696, -0.53169791272852962, 0.84582565657124209},
                            {-0.29560012757901205, 0.0057399674549712312, 0.95529451864275239},
                            {-0.97693553466246352, -0.17675714423678687, 0.11980765031926001},
                            {-0.48882913884257762, 0.22923747086504817, -0.84172219584006469}};
  const double expected[4] = {-168.656134439, 830.459863373, -260.982754997, 55.070630023};
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(config.heights->crater_marks(at[k], 100.0).floor, 0.9);
    EXPECT_NEAR(config.heights->height(at[k]), expected[k], 1e-6) << "place " << k;
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
