// The shipped elevation grids (data/elevation/*, each with its SOURCE.md):
// the samples read by hand from the sources, and the named places the
// program's terrain must show, each against its real height within what
// the grid's resolution explains. Prints the table of places.
#include "terrain/grid_height.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"
#include "terrain/terrain_surface.h"

#include "sim/body.h"
#include "sim/geodesy.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

struct Loaded {
  Body body;
  TerrainConfig config;
  const GridHeight* grid = nullptr;
};

Loaded load(const std::string& name) {
  Loaded l;
  l.body = load_body(find_body_file(name));
  l.config = parse_terrain(l.body);
  l.grid = dynamic_cast<const GridHeight*>(l.config.heights.get());
  return l;
}

glm::dvec3 planetocentric(double lat_deg, double lon_deg) {
  double lat = glm::radians(lat_deg), lon = glm::radians(lon_deg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

TEST(GridDataTest, ShippedGridsHoldTheSamplesReadByHand) {
  // The values SOURCE.md lists, read from the sources with a separate tool.
  Loaded earth = load("earth"), mars = load("mars"), moon = load("moon");
  ASSERT_TRUE(earth.grid && mars.grid && moon.grid) << "a body lost its grid";
  const GridData& e = earth.grid->data();
  EXPECT_EQ(e.sample(1043, 744), 6096.0);    // nearest Everest
  EXPECT_EQ(e.sample(82, 530), 1782.0);      // nearest Mont Blanc
  EXPECT_EQ(e.sample(1708, 944), -10376.0);  // the deepest node
  EXPECT_EQ(e.sample(1711, 944), -10136.0);  // nearest the Challenger Deep
  EXPECT_EQ(e.sample(0, 2160), 2810.0);      // the South Pole
  EXPECT_EQ(e.sample(0, 0), -4290.0);        // the North Pole
  EXPECT_EQ(earth.grid->range().min, 0.0);   // under the sea's surface
  const GridData& m = mars.grid->data();
  EXPECT_EQ(m.sample(907, 290), 21134.0);  // the highest sample, Olympus Mons
  EXPECT_EQ(m.sample(248, 491), -8068.0);  // the lowest, Hellas
  EXPECT_EQ(m.sample(0, 0), -1971.0);
  EXPECT_EQ(m.sample(0, 719), 3806.0);
  const GridData& l = moon.grid->data();
  EXPECT_EQ(l.sample(1394, 533), -1858.5);  // Tycho's central peak
  EXPECT_EQ(l.sample(1395, 531), -3465.5);  // Tycho's floor, lowest
  EXPECT_EQ(l.sample(1399, 528), 1426.5);   // Tycho's rim, highest
  EXPECT_EQ(l.sample(805, 338), 10504.0);   // the highest sample
  EXPECT_EQ(l.sample(750, 641), -8878.5);   // the lowest (the label says one count lower)
  std::printf("grid memory: Earth %.1f MB, Mars %.1f MB, Moon %.1f MB\n",
              double(e.memory_bytes()) / 1e6, double(m.memory_bytes()) / 1e6,
              double(l.memory_bytes()) / 1e6);
}

struct Place {
  const char* name;
  const char* body;
  double lat_deg, lon_deg;  // geodetic on Earth, planetocentric elsewhere
  double real_m;
  double tolerance_m;
  const char* why;
};

// Tolerances: what a grid of this spacing can miss at the place, from the
// relief around it (the real ground's span within one grid spacing).
const Place kPlaces[] = {
    {"Everest", "earth", 27.9881, 86.925, 8849, 3800,
     "ETOPO5 nodes 9 km apart; within 9 km of the summit the ground falls to ~5100 m (Khumbu)"},
    {"Mont Blanc", "earth", 45.8326, 6.8652, 4806, 3400,
     "ETOPO5 nodes 9 km apart; within 9 km the ground falls to ~1400 m (Bossons, Val Veny)"},
    {"Challenger Deep", "earth", 11.3733, 142.5917, -10935, 2400,
     "ETOPO5 nodes 9 km apart; the trench's walls rise ~2.4 km within 9 km of its axis"},
    {"Olympus Mons, highest sample", "mars", 17.375, 226.875, 21900, 1000,
     "MOLA cells 14.8 km wide hold their median; the summit is a narrow rim crest"},
    {"Olympus Mons, IAU centre", "mars", 18.65, 226.2, 21900, 3200,
     "the centre lies in the caldera, up to 3.2 km below the summit"},
    {"Hellas floor, lowest sample", "mars", -32.875, 62.125, -8200, 400,
     "MOLA's lowest shots reach -8.2 km; a 14.8 km cell's median stays above them"},
};

TEST(GridDataTest, NamedPlacesStandWithinWhatTheGridsResolutionExplains) {
  Loaded earth = load("earth"), mars = load("mars"), moon = load("moon");
  ASSERT_TRUE(earth.grid && mars.grid && moon.grid);
  Geodesy earth_geodesy(earth.body.shape);
  std::printf("%-30s %10s %10s %10s %10s  %s\n", "place", "model m", "grid m", "real m", "within m",
              "why");
  for (const Place& p : kPlaces) {
    const Loaded& l = std::string(p.body) == "earth" ? earth : mars;
    glm::dvec3 dir = std::string(p.body) == "earth"
                         ? glm::normalize(earth_geodesy.body_from_geodetic(
                               {glm::radians(p.lat_deg), glm::radians(p.lon_deg), 0.0}))
                         : planetocentric(p.lat_deg, p.lon_deg);
    double model = l.grid->seabed_height(dir), grid = l.grid->nearest_sample(dir);
    std::printf("%-30s %10.0f %10.0f %10.0f %10.0f  %s\n", p.name, model, grid, p.real_m,
                p.tolerance_m, p.why);
    EXPECT_LE(std::abs(model - p.real_m), p.tolerance_m) << p.name;
    // The model honours the grid: within the bounds its samples nearby give.
    HeightRange near = l.grid->range_near(dir, 0.0);
    EXPECT_GE(l.grid->height(dir), near.min) << p.name;
    EXPECT_LE(l.grid->height(dir), near.max) << p.name;
  }
  // Tycho (43.31 S, 11.36 W): its floor's lowest sample and its rim's
  // highest, 30 km apart; the crater is 4.8 km deep from rim to floor
  // (Pike 1977), which 7.6 km cells blunt by a few hundred metres at each.
  double floor = moon.grid->seabed_height(planetocentric(-42.875, -11.125));
  double rim = moon.grid->seabed_height(planetocentric(-42.125, -10.125));
  double peak = moon.grid->seabed_height(planetocentric(-43.31, -11.36));
  std::printf("%-30s %10.0f %10.0f %10s %10s  %s\n", "Tycho floor", floor,
              moon.grid->nearest_sample(planetocentric(-42.875, -11.125)), "-", "-",
              "LOLA cells 7.6 km wide");
  std::printf("%-30s %10.0f %10.0f %10s %10s  %s\n", "Tycho rim", rim,
              moon.grid->nearest_sample(planetocentric(-42.125, -10.125)), "-", "-",
              "LOLA cells 7.6 km wide");
  std::printf("%-30s %10.0f %10.0f %10s %10s  %s\n", "Tycho central peak", peak,
              moon.grid->nearest_sample(planetocentric(-43.31, -11.36)), "-", "-",
              "rises ~2 km over the floor");
  std::printf("%-30s %10.0f %10.0f %10.0f %10.0f  %s\n", "Tycho, rim over floor", rim - floor,
              moon.grid->nearest_sample(planetocentric(-42.125, -10.125)) -
                  moon.grid->nearest_sample(planetocentric(-42.875, -11.125)),
              4800.0, 700.0, "7.6 km cells blunt the rim crest and the floor");
  EXPECT_LE(std::abs(rim - floor - 4800.0), 700.0);
  EXPECT_GT(peak, floor + 1000.0) << "Tycho's central peak is gone";
}

TEST(GridDataTest, GroundUnderAPlaceIsTheGridsHeight) {
  // What `planet probe ground` prints: Everest and Olympus Mons from the
  // grids (the procedural ground had them at 2049 m and -1869 m).
  for (const char* name : {"earth", "mars"}) {
    Loaded l = load(name);
    ASSERT_TRUE(l.grid);
    Geodesy geodesy(l.body.shape);
    TerrainSurface surface(l.body.shape, l.config);
    Geodetic place = std::string(name) == "earth"
                         ? Geodetic{glm::radians(27.9881), glm::radians(86.925), 0.0}
                         : Geodetic{glm::radians(18.65), glm::radians(-133.8), 0.0};
    double ground = ground_height(surface, geodesy, place);
    glm::dvec3 dir = glm::normalize(geodesy.body_from_geodetic(place));
    EXPECT_NEAR(ground, l.grid->height(dir), 1.0) << name;
    EXPECT_GT(ground, std::string(name) == "earth" ? 5000.0 : 18000.0) << name;
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
