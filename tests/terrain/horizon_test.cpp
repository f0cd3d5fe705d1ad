// Terrain shadows' horizons: against a fine march over the ground itself,
// their coding, and their independence from what the memo held.
#include "terrain/horizon.h"
#include "terrain/cube_sphere.h"
#include "terrain/tile_mesh.h"

#include "core/data_paths.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TerrainSurface load_surface(const std::filesystem::path& file) {
  Body body = load_body(file);
  return TerrainSurface(body.shape, parse_terrain(body));
}

TileKey key_at(double lat_deg, double lon_deg, int level) {
  double lat = glm::radians(lat_deg), lon = glm::radians(lon_deg);
  FacePoint f =
      sphere_to_cube({std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
  auto cell = [&](double u) { return uint32_t(std::floor(0.5 * (u + 1.0) * double(1 << level))); };
  return {f.face, level, cell(f.s), cell(f.t)};
}

// The horizon's elevation from a grid vertex along grid direction k,
// marched over the height source itself in quarter grid steps near the
// vertex, and in steps of 1/64 of the distance beyond, out to 4000 grid
// steps.
double marched_horizon(const TerrainSurface& surface, const TileKey& key, int i, int j, int k) {
  const double step = key.size() / (kTileGrid - 1);
  const double s = key.s0() + step * i, t = key.t0() + step * j;
  const glm::dvec3 x = surface.face_point(key.face, s, t);
  const glm::dvec3 up = glm::normalize(x);
  double best = -1.0;
  for (double u = 0.25; u <= 4000.0; u += std::max(0.25, u / 64.0)) {
    glm::dvec3 d = surface.face_point(key.face, s + step * u * kHorizonStep[k][0],
                                      t + step * u * kHorizonStep[k][1]) -
                   x;
    best = std::max(best, glm::dot(d, up) / glm::length(d));
  }
  return std::asin(best);
}

struct Agreement {
  int cases = 0, agree = 0;
  int shadowed = 0;  // by the march: lit everywhere would agree on the rest alone
  double rate() const { return double(agree) / cases; }
};

// Whether the tile's vertices are in the shadow of a sun at each elevation
// in each grid direction, against the march: the share of cases that agree.
Agreement shadow_agreement(const TerrainSurface& surface, const TileKey& key) {
  TileMesh tile = build_tile(surface, key);
  Agreement a;
  for (int j = 2; j < kTileGrid; j += 5) {
    for (int i = 2; i < kTileGrid; i += 5) {
      for (int k = 0; k < kHorizonDirections; ++k) {
        double marched = marched_horizon(surface, key, i, j, k);
        double built = decode_horizon(tile.vertices[size_t(j * kTileGrid + i)].horizon[k]);
        for (double sun_deg : {1.0, 2.0, 4.0, 8.0, 16.0}) {
          double sun = glm::radians(sun_deg);
          // Within the drawn penumbra (a quarter degree) either is right.
          if (std::abs(sun - marched) < glm::radians(0.25)) continue;
          ++a.cases;
          a.agree += (sun > built) == (sun > marched);
          a.shadowed += sun < marched;
        }
      }
    }
  }
  return a;
}

TEST(HorizonTest, ShadowsAgreeWithAMarchOverTheGroundOnEarthAndMars) {
  // A tile in the Alps of 90 m grid steps, one on Mars's Gale crater rim of
  // 65 m, and coarser ones whose horizons come mostly from their ancestors.
  // On the procedural bodies, rough at every scale: on the elevation grids,
  // smooth below 9 km, the Alps' level-16 tile agrees in 94.8 % of cases,
  // the misses on slopes as steep as the sun is high.
  const TerrainSurface earth =
      load_surface(project_root() / "tests/data/planets/earth_procedural.json");
  const TerrainSurface mars =
      load_surface(project_root() / "tests/data/planets/mars_procedural.json");
  struct Case {
    const TerrainSurface* surface;
    TileKey key;
    double min_rate;
  } cases[] = {
      {&earth, key_at(46.55, 7.98, 12), 0.95},
      {&earth, key_at(46.55, 7.98, 16), 0.95},
      {&mars, key_at(-4.6, 137.4, 12), 0.95},
      {&mars, key_at(-5.0, 137.8, 15), 0.95},
  };
  for (const Case& c : cases) {
    Agreement a = shadow_agreement(*c.surface, c.key);
    SCOPED_TRACE(c.key.name());
    EXPECT_GT(a.cases, 1000);
    EXPECT_GE(a.rate(), c.min_rate) << a.agree << " of " << a.cases;
    // Enough shadow that a sun never hidden would fail.
    EXPECT_GT(a.shadowed, int((1.0 - c.min_rate) * a.cases) * 2) << a.shadowed;
    std::printf("%s: shadow agrees with the march in %d of %d cases (%.1f %%), %d in shadow\n",
                c.key.name().c_str(), a.agree, a.cases, 100.0 * a.rate(), a.shadowed);
  }
}

TEST(HorizonTest, ATileSplitFlipsFewShadows) {
  // Where a tile splits, its children's vertices at the parent's grid
  // points take over: a shadow that flips there pops, the only way these
  // shadows can move over the ground as the camera does. Measured per
  // grid point and direction, over suns from 1 to 16 degrees. On the
  // procedural bodies: their rough ground casts shadows at this level,
  // where the elevation grids' (9 and 15 km between samples) is smooth.
  const TerrainSurface earth =
      load_surface(project_root() / "tests/data/planets/earth_procedural.json");
  const TerrainSurface mars =
      load_surface(project_root() / "tests/data/planets/mars_procedural.json");
  for (const auto& [surface, parent_key] :
       {std::pair{&earth, key_at(46.55, 7.98, 11)}, std::pair{&mars, key_at(-3.9, 137.6, 11)}}) {
    TileMesh parent = build_tile(*surface, parent_key);
    int cases = 0, flips = 0, shadowed = 0;
    for (int c = 0; c < 4; ++c) {
      TileKey child{parent_key.face, parent_key.level + 1, 2 * parent_key.x + (c & 1),
                    2 * parent_key.y + (c >> 1)};
      TileMesh tile = build_tile(*surface, child);
      for (int j = 0; j < kTileGrid; j += 2) {
        for (int i = 0; i < kTileGrid; i += 2) {
          int pi = (c & 1) * (kTileGrid - 1) / 2 + i / 2,
              pj = (c >> 1) * (kTileGrid - 1) / 2 + j / 2;
          const TileVertex& a = tile.vertices[size_t(j * kTileGrid + i)];
          const TileVertex& b = parent.vertices[size_t(pj * kTileGrid + pi)];
          for (int k = 0; k < kHorizonDirections; ++k) {
            for (double sun_deg : {1.0, 2.0, 4.0, 8.0, 16.0}) {
              double sun = glm::radians(sun_deg);
              bool in_a = sun < decode_horizon(a.horizon[k]);
              bool in_b = sun < decode_horizon(b.horizon[k]);
              ++cases;
              flips += in_a != in_b;
              shadowed += in_b;
            }
          }
        }
      }
    }
    std::printf("%s: a split flips the shadow in %d of %d cases (%.1f %%), %d in shadow\n",
                parent_key.name().c_str(), flips, cases, 100.0 * flips / cases, shadowed);
    EXPECT_GT(shadowed, cases / 10);
    EXPECT_LT(double(flips) / cases, 0.05);
  }
}

TEST(HorizonTest, CodingKeepsLowAnglesToATenthOfADegree) {
  for (double deg = -90.0; deg <= 90.0; deg += 0.05) {
    float a = float(glm::radians(deg));
    double back = glm::degrees(double(decode_horizon(encode_horizon(a))));
    double allowed = std::abs(deg) <= 1.0 ? 0.1 : std::abs(deg) <= 20.0 ? 0.4 : 1.5;
    ASSERT_NEAR(back, deg, allowed) << deg;
  }
  EXPECT_EQ(encode_horizon(-10.0f), 0);
  EXPECT_EQ(encode_horizon(10.0f), 255);
}

TEST(HorizonTest, ATilesHorizonsDoNotDependOnWhatTheMemoHeld) {
  // A tile built alone (its ancestors' horizons computed on the way) and
  // one built after its ancestors and hundreds of others, as a cache
  // would: byte for byte the same vertices.
  const TileKey key = key_at(46.55, 7.98, 11);
  std::vector<TileVertex> alone =
      build_tile(load_surface(data_dir() / "planets" / "earth.json"), key).vertices;

  const TerrainSurface earth = load_surface(data_dir() / "planets" / "earth.json");
  for (TileKey k = key; k.level > 0;) {
    k = k.parent();
    build_tile(earth, k);
  }
  for (uint32_t n = 0; n < 300; ++n) {  // more than the memo keeps
    earth.horizon_memo().keep({(key.face + 1) % 6, 14, n, 7},
                              std::make_shared<const HorizonField>());
  }
  EXPECT_LT(earth.horizon_memo().size(), 300u);
  std::vector<TileVertex> cached = build_tile(earth, key).vertices;
  ASSERT_EQ(alone.size(), cached.size());
  EXPECT_EQ(std::memcmp(alone.data(), cached.data(), alone.size() * sizeof(TileVertex)), 0);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
