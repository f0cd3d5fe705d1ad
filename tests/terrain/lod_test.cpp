// Level of detail over a flight from 2 m to 400 km, culling, and the
// tile cache's memory over a long flight.
#include "terrain/lod.h"
#include "terrain/tile_cache.h"

#include "core/data_paths.h"
#include "sim/geodesy.h"
#include "terrain/cube_sphere.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <unistd.h>
#include <chrono>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <random>
#include <unordered_map>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

LodView view_at(const Geodesy& geodesy, const Geodetic& place, double heading, double pitch,
                int height_px) {
  LodView v;
  Camera camera = geodesy.camera_at(place, heading, pitch, Camera().vertical_fov);
  v.eye_body = camera.pos_body;
  v.view_from_body = glm::mat3_cast(glm::conjugate(camera.body_from_camera));
  v.tan_half_fov_y = std::tan(glm::radians(30.0));
  v.aspect = 16.0 / 9.0;
  v.height_px = height_px;
  return v;
}

// Builds what the selection wants until it wants nothing: what a capture does.
struct SyncTiles {
  const TerrainSurface& surface;
  std::unordered_map<TileKey, TileMesh, TileKeyHash> tiles;
  LodSelection select_complete(const LodView& view) {
    LodSelector selector(surface);
    while (true) {
      LodSelection sel = selector.select(view, [&](const TileKey& k, ResidentTile& t) {
        auto it = tiles.find(k);
        if (it == tiles.end()) return false;
        t = {it->second.error, it->second.heights};
        return true;
      });
      if (sel.wanted.empty()) return sel;
      for (const TileKey& k : sel.wanted) tiles.emplace(k, build_tile(surface, k));
    }
  }
};

// On each body standing on an elevation grid, over its roughest ground:
// the Alps, Olympus Mons' caldera, Tycho.
TEST(LodTest, FlightFrom2mTo400kmKeepsDrawnErrorUnderBudget) {
  struct Place {
    const char* body;
    double lat_deg, lon_deg;
  };
  for (const Place& p :
       {Place{"earth", 46.55, 7.98}, Place{"mars", 18.35, -133.4}, Place{"moon", -43.31, -11.36}}) {
    SCOPED_TRACE(p.body);
    Body body = load_body(data_dir() / "planets" / (std::string(p.body) + ".json"));
    TerrainSurface surface(body.shape, parse_terrain(body));
    Geodesy geodesy(body.shape);
    SyncTiles sync{surface, {}};
    Geodetic place{glm::radians(p.lat_deg), glm::radians(p.lon_deg), 0.0};
    double ground = 0;
    surface.point(glm::normalize(geodesy.body_from_geodetic(place)), &ground);
    // 270 lines keeps the test quick; the error bound scales with the image.
    const int kLines = 270;
    std::printf("%s: height_m tiles_drawn triangles tiles_resident max_error_px deepest\n", p.body);
    for (double above : {2.0, 20.0, 200.0, 2e3, 10e3, 50e3, 150e3, 400e3}) {
      place.height = ground + above;
      LodView view = view_at(geodesy, place, glm::radians(60.0), glm::radians(-10.0), kLines);
      LodSelection sel = sync.select_complete(view);
      ASSERT_FALSE(sel.tiles.empty());
      double worst = 0;
      int deepest = 0;
      for (const SelectedTile& t : sel.tiles) {
        deepest = std::max(deepest, t.key.level);
        if (t.key.level < surface.config().max_level) worst = std::max(worst, t.error_px);
      }
      std::printf("%8.0f %11zu %9zu %14zu %12.3f %7d\n", above, sel.tiles.size(),
                  sel.tiles.size() * tile_indices().size() / 3, sync.tiles.size(), worst, deepest);
      EXPECT_LE(worst, view.pixel_budget) << "at " << above << " m";
      EXPECT_LT(deepest, surface.config().max_level) << "the quadtree is deep enough at " << above;
    }
  }
}

// One selector kept over the flight (its tiles' bounds computed once and
// reused) chooses exactly the tiles, distances and errors that a selector
// made fresh for every frame chooses, up and back down again.
TEST(LodTest, BoundsKeptAcrossFramesSelectTheSameTilesAsFreshOnes) {
  Body body = load_body(data_dir() / "planets" / "earth.json");
  TerrainSurface surface(body.shape, parse_terrain(body));
  Geodesy geodesy(body.shape);
  SyncTiles sync{surface, {}};
  LodSelector kept(surface);
  Geodetic place{glm::radians(46.55), glm::radians(7.98), 0.0};
  double ground = 0;
  surface.point(glm::normalize(geodesy.body_from_geodetic(place)), &ground);
  std::vector<double> heights = {2.0, 20.0, 200.0, 2e3, 10e3, 50e3, 150e3, 400e3};
  heights.insert(heights.end(), heights.rbegin() + 1, heights.rend());
  int frame = 0;
  for (double above : heights) {
    place.height = ground + above;
    LodView view = view_at(geodesy, place, glm::radians(60.0 + frame), glm::radians(-10.0), 270);
    LodSelection fresh = sync.select_complete(view);
    LodSelection reused = kept.select(view, [&](const TileKey& k, ResidentTile& t) {
      auto it = sync.tiles.find(k);
      if (it == sync.tiles.end()) return false;
      t = {it->second.error, it->second.heights};
      return true;
    });
    ASSERT_EQ(reused.tiles.size(), fresh.tiles.size()) << "at " << above << " m";
    for (size_t i = 0; i < fresh.tiles.size(); ++i) {
      EXPECT_EQ(reused.tiles[i].key.packed(), fresh.tiles[i].key.packed());
      EXPECT_EQ(reused.tiles[i].distance, fresh.tiles[i].distance);
      EXPECT_EQ(reused.tiles[i].error_px, fresh.tiles[i].error_px);
    }
    EXPECT_TRUE(reused.wanted.empty());
    ++frame;
  }
}

TEST(LodTest, HorizonCullingNeverDropsAVisiblePoint) {
  // A tile the horizon test drops must lie wholly behind the occluder
  // sphere: every grid vertex hidden from the eye by it. Checked from
  // heights of 1 m to 1000 km over tiles of several levels around.
  Body body = load_body(data_dir() / "planets" / "earth.json");
  TerrainSurface surface(body.shape, parse_terrain(body));
  LodSelector selector(surface);
  Geodesy geodesy(body.shape);
  const double R = surface.occluder_radius();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int culled = 0;
  for (int k = 0; k < 16; ++k) {
    Geodetic place{glm::radians(46.55), glm::radians(7.98), std::pow(10.0, 6.0 * u(rng))};
    LodView view = view_at(geodesy, place, 0, 0, 270);
    FacePoint fp = sphere_to_cube(glm::normalize(view.eye_body));
    for (int level : {3, 5, 7}) {
      double n = double(1u << level);
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          int x = int((fp.s + 1) / 2 * n) + dx * (1 << (level - 3)) * 3;
          int y = int((fp.t + 1) / 2 * n) + dy * (1 << (level - 3)) * 3;
          if (x < 0 || y < 0 || x >= n || y >= n) continue;
          TileKey key{fp.face, level, uint32_t(x), uint32_t(y)};
          if (selector.above_horizon(surface.bounds(key), view)) continue;
          ++culled;
          TileMesh tile = build_tile(surface, key);
          for (int i = 0; i < kTileGrid * kTileGrid; ++i) {
            glm::dvec3 p = tile.center_body + glm::dvec3(tile.vertices[size_t(i)].offset);
            glm::dvec3 d = p - view.eye_body;
            double len = glm::length(d);
            d /= len;
            // Does the segment eye -> p pass through the occluder sphere?
            double b = glm::dot(view.eye_body, d);
            double c = glm::dot(view.eye_body, view.eye_body) - R * R;
            double disc = b * b - c;
            double t = -b - std::sqrt(std::max(disc, 0.0));
            ASSERT_TRUE(disc > 0 && t > 0 && t < len)
                << "tile " << key.name() << " culled but vertex " << i << " visible from "
                << place.height << " m";
          }
        }
      }
    }
  }
  EXPECT_GT(culled, 10) << "the test must exercise culling";
}

size_t resident_set_bytes() {
  std::ifstream statm("/proc/self/statm");
  size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * size_t(sysconf(_SC_PAGESIZE));
}

// Heights that, once armed, answer only when let go: to the cache, a tile
// that never finishes (a worker stuck in it).
class StuckHeights final : public HeightSource {
 public:
  double height(const glm::dvec3&) const override {
    std::unique_lock lock(mutex_);
    let_go_.wait(lock, [&] { return !armed_; });
    return 0.0;
  }
  HeightRange range_near(const glm::dvec3&, double) const override { return {}; }
  HeightRange range() const override { return {}; }
  double interpolation_error(double) const override { return 0.0; }
  void arm(bool armed) {
    {
      std::lock_guard lock(mutex_);
      armed_ = armed;
    }
    let_go_.notify_all();
  }

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable let_go_;
  bool armed_ = false;
};

TEST(TileCacheTest, ATileThatNeverFinishesEndsTheWaitAndTheCache) {
  Body body = load_body(data_dir() / "planets" / "mars.json");
  body.terrain = nullptr;
  TerrainConfig config = parse_terrain(body);
  auto stuck = std::make_shared<StuckHeights>();
  config.heights = stuck;
  TerrainSurface surface(body.shape, config);
  stuck->arm(true);
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  const TileKey key{2, 0, 0, 0};
  auto began = Clock::now();
  double waited = 0;
  {
    TileCache cache(surface, size_t(1) << 20, 1);
    cache.request({key});
    std::vector<TileKey> missing = cache.wait_for({key}, 0.5);
    waited = seconds_since(began);
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_TRUE(missing[0] == key);
    EXPECT_GE(waited, 0.5);
    began = Clock::now();
  }  // the worker, still in the tile, is left behind
  double stopping = seconds_since(began);
  std::printf("the wait gave up after %.2f s, the cache went after %.2f s\n", waited, stopping);
  // Its bound, with room for a loaded machine: the point is that it ends.
  EXPECT_LT(stopping, TileCache::kWorkerStopSeconds + 10.0);
  // Let go, the worker left behind finishes its tile on the state it holds.
  stuck->arm(false);
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAddressSanitizer = true;
#elif defined(__has_feature)
constexpr bool kUnderAddressSanitizer = __has_feature(address_sanitizer);
#else
constexpr bool kUnderAddressSanitizer = false;
#endif

TEST(TileCacheTest, LongFlightStaysUnderBudgetWithoutGrowth) {
  // 3000 frames of a window's loop (select, request, use, evict; never
  // waiting) on a smooth Mars-sized ellipsoid, whose tiles are cheap to
  // build, flying low around the body and climbing: the cache keeps
  // turning over, must stay under budget, and the process must not grow.
  Body body = load_body(data_dir() / "planets" / "mars.json");
  body.terrain = nullptr;  // smooth: the cache is what is tested here
  TerrainSurface surface(body.shape, parse_terrain(body));
  Geodesy geodesy(body.shape);
  LodSelector selector(surface);
  const size_t budget = size_t(6) << 20;
  TileCache cache(surface, budget, 1);
  size_t rss_warm = 0, worst_bytes = 0;
  for (int frame = 1; frame <= 3000; ++frame) {
    double f = frame / 3000.0;
    Geodetic place{glm::radians(30.0 * std::sin(6.0 * f)), glm::radians(-180.0 + 720.0 * f),
                   50.0 + 2e5 * f * f};
    LodView view = view_at(geodesy, place, glm::radians(90.0), glm::radians(-20.0), 270);
    LodSelection sel = selector.select(
        view, [&](const TileKey& k, ResidentTile& t) { return cache.lookup(k, t); });
    cache.request(sel.wanted);
    for (const SelectedTile& t : sel.tiles) ASSERT_TRUE(cache.use(t.key, uint64_t(frame)));
    cache.evict(uint64_t(frame));
    worst_bytes = std::max(worst_bytes, cache.bytes());
    if (frame % 4 == 0) cache.wait_for(sel.wanted, 1.0);  // let the worker keep up
    if (frame == 500) rss_warm = resident_set_bytes();
  }
  size_t rss_end = resident_set_bytes();
  std::printf("tiles built %llu, resident at most %.1f MiB of %.1f, process %.1f -> %.1f MiB\n",
              (unsigned long long)cache.tiles_built(), double(worst_bytes) / 1048576.0,
              double(budget) / 1048576.0, double(rss_warm) / 1048576.0,
              double(rss_end) / 1048576.0);
  EXPECT_GT(cache.tiles_built(), budget / (kTileVertexCount * sizeof(TileVertex)))
      << "the flight must overflow the cache";
  // Tiles finished by the worker after the last eviction may add a few.
  EXPECT_LE(worst_bytes, budget + 8 * kTileVertexCount * sizeof(TileVertex));
  // Allocator slack only: well under the budget itself. Not under
  // AddressSanitizer, whose quarantine keeps freed blocks (256 MiB of them)
  // from reuse, so that the process grows by design; LeakSanitizer checks
  // there, at exit, what this bound checks here.
  if (!kUnderAddressSanitizer) {
    EXPECT_LT(double(rss_end), double(rss_warm) + 0.5 * double(budget));
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
