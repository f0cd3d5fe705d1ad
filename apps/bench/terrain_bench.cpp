// Terrain: LOD selection CPU time, tile generation per core, and frame
// time of terrain + sky at 1280x720 on Earth from the ground, 10 km and
// 400 km (GPU time from timer queries, tiles all resident first).
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "gl/pass_tally.h"
#include "render/frame.h"
#include "sim/geodesy.h"
#include "sim/star_catalogue.h"
#include "sim/sun_ephemeris.h"
#include "sim/utc_time.h"
#include "terrain/horizon.h"
#include "terrain/lod.h"
#include "terrain/sun_shadow_field.h"
#include "terrain/tile_mesh.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/constants.hpp>

#include <chrono>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

namespace planet {
namespace {

Body earth() { return load_body(data_dir() / "planets" / "earth.json"); }

// Above the Bernese Alps (or `lat_deg`, `lon_deg`), `above` metres over
// the ground, looking east and down.
Camera camera_above(const Body& body, const TerrainSurface& surface, double above,
                    double lat_deg = 46.55, double lon_deg = 7.98) {
  Geodesy geodesy(body.shape);
  Geodetic place{glm::radians(lat_deg), glm::radians(lon_deg), 0.0};
  double ground = 0;
  surface.point(glm::normalize(geodesy.body_from_geodetic(place)), &ground);
  place.height = ground + above;
  double pitch = above < 100 ? 4.0 : above < 50e3 ? -15.0 : -30.0;
  return geodesy.camera_at(place, glm::radians(60.0), glm::radians(pitch), Camera().vertical_fov);
}

// Times a benchmark's frames: each iteration renders one (`render`
// returns its FrameStats) and takes the sum of its passes' wall time; then
// each counter of `counted` is the mean wall time a frame of the passes
// named for it. The frames' table of passes (PassTally::table, as `fly
// --pass-table` prints it) comes before the benchmark's own line.
struct PassCounter {
  const char* counter;
  std::vector<std::string> passes;
};

// Frames after the first take the tiles that are resident, as a window
// does: the first waits for all of them.
void set_terrain_wait(FrameRenderer& renderer, double seconds) {
  FrameOptions options = renderer.options();
  options.terrain_wait_s = seconds;
  renderer.set_options(options);
}

template <class Render>
void time_frames(benchmark::State& state, Render render, const std::vector<PassCounter>& counted) {
  std::unordered_map<std::string, double> totals;
  PassTally tally;
  for (auto _ : state) {
    FrameStats stats = render();
    tally.add(stats.passes);
    double frame_ms = 0;
    for (const auto& p : stats.passes) {
      frame_ms += p.wall_ms;
      totals[p.pass] += p.wall_ms;
    }
    state.SetIterationTime(frame_ms * 1e-3);
  }
  for (const PassCounter& c : counted) {
    double sum = 0;
    for (const std::string& pass : c.passes) sum += totals[pass];
    state.counters[c.counter] = sum / double(state.iterations());
  }
  std::printf("the next benchmark's frames, each pass's mean wall and GPU time:\n%s",
              tally.table().c_str());
  std::fflush(stdout);
}

// The selection over a body's ground, `above` metres over it at a place.
void time_lod_selection(benchmark::State& state, const Body& body, double above, double lat_deg,
                        double lon_deg) {
  TerrainSurface surface(body.shape, parse_terrain(body));
  LodSelector selector(surface);
  Camera camera = camera_above(body, surface, above, lat_deg, lon_deg);
  LodView view;
  view.eye_body = camera.pos_body;
  view.view_from_body = glm::mat3_cast(glm::conjugate(camera.body_from_camera));
  view.height_px = 720;
  std::unordered_map<TileKey, ResidentTile, TileKeyHash> tiles;
  auto lookup = [&](const TileKey& k, ResidentTile& t) {
    auto it = tiles.find(k);
    if (it == tiles.end()) return false;
    t = it->second;
    return true;
  };
  // Make every tile the view needs resident, as a settled frame has it.
  for (LodSelection sel = selector.select(view, lookup); !sel.wanted.empty();
       sel = selector.select(view, lookup)) {
    for (const TileKey& k : sel.wanted) {
      TileMesh m = build_tile(surface, k);
      tiles[k] = {m.error, m.heights};
    }
  }
  size_t drawn = 0;
  for (auto _ : state) {
    LodSelection sel = selector.select(view, lookup);
    drawn = sel.tiles.size();
    benchmark::DoNotOptimize(sel);
  }
  state.counters["tiles_drawn"] = double(drawn);
  state.counters["triangles"] = double(drawn * tile_indices().size() / 3);
}

void BM_TerrainLodSelection(benchmark::State& state) {
  time_lod_selection(state, earth(), double(state.range(0)), 46.55, 7.98);
}
BENCHMARK(BM_TerrainLodSelection)->Arg(2)->Arg(10000)->Arg(400000)->Unit(benchmark::kMicrosecond);

// The same on Mars over Olympus Mons' caldera and on the Moon over Tycho.
void BM_TerrainLodSelectionOn(benchmark::State& state, const char* name, double lat_deg,
                              double lon_deg) {
  Body body = load_body(data_dir() / "planets" / (std::string(name) + ".json"));
  time_lod_selection(state, body, double(state.range(0)), lat_deg, lon_deg);
}
BENCHMARK_CAPTURE(BM_TerrainLodSelectionOn, mars, "mars", 18.35, -133.4)
    ->Arg(2)
    ->Arg(10000)
    ->Arg(400000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TerrainLodSelectionOn, moon, "moon", -43.31, -11.36)
    ->Arg(2)
    ->Arg(10000)
    ->Arg(400000)
    ->Unit(benchmark::kMicrosecond);

// `detail` false: the body's grid without its detail (grid_detail.h), its
// interpolation alone, for the detail's cost in the same run.
void BM_TerrainTileBuild(benchmark::State& state, const char* name, bool detail) {
  Body body = load_body(data_dir() / "planets" / (std::string(name) + ".json"));
  if (!detail) body.terrain["height"].erase("detail");
  TerrainSurface surface(body.shape, parse_terrain(body));
  uint32_t i = 0;
  for (auto _ : state) {
    // Tiles of level 12 along a row: the ground a low flight needs. As in
    // flight, each tile's parent was built before it (its far horizon
    // kept, terrain/horizon.h); that build is not timed here.
    TileKey key{2, 12, 1000 + (i++ % 500), 2000};
    state.PauseTiming();
    benchmark::DoNotOptimize(surface.horizon_memo().far(surface, key.parent()));
    state.ResumeTiming();
    TileMesh m = build_tile(surface, key);
    benchmark::DoNotOptimize(m);
  }
  state.counters["tiles_per_s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_TerrainTileBuild, earth, "earth", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, earth_grid_only, "earth", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, mars, "mars", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, mars_grid_only, "mars", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, moon, "moon", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, moon_grid_only, "moon", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, asteroid, "asteroid", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainTileBuild, eros, "eros", true)->Unit(benchmark::kMillisecond);

// The part of a tile build that is the shadows' own: sampling the grid's
// border and marching its horizons (the parent's far horizon kept, as a
// cache's build finds it).
void BM_TerrainHorizons(benchmark::State& state, const char* name) {
  Body body = load_body(data_dir() / "planets" / (std::string(name) + ".json"));
  TerrainSurface surface(body.shape, parse_terrain(body));
  const TileKey key{2, 12, 1000, 2000};
  auto parent = surface.horizon_memo().far(surface, key.parent());
  const BorderedGrid grid = sample_grid(surface, key);
  double march_s = 0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    TileHorizons h = compute_horizons(grid, key, parent.get());
    march_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(h);
    benchmark::DoNotOptimize(sample_grid(surface, key));
  }
  const double n = double(state.iterations());
  state.counters["march_ms"] = 1e3 * march_s / n;
  state.counters["grid_points"] = double(BorderedGrid::kSide * BorderedGrid::kSide);
}
BENCHMARK_CAPTURE(BM_TerrainHorizons, earth, "earth")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TerrainHorizons, mars, "mars")->Unit(benchmark::kMillisecond);

// The terrain's shadow in the air (sun_shadow_field.h) over the Alps,
// 3000 m up, the sun range(0) tenths of a degree high in the west-north-
// west: a new patch (its ground sampled, then the shadow marched), and the
// shadow alone for a sun that moved (the patch kept), on the CPU's cores.
void BM_TerrainShadowField(benchmark::State& state) {
  Body body = earth();
  TerrainSurface surface(body.shape, parse_terrain(body));
  Camera camera = camera_above(body, surface, 3000.0);
  Geodesy geodesy(body.shape);
  const glm::dmat3 enu = geodesy.body_from_enu(geodesy.geodetic_from_body(camera.pos_body));
  const double e = glm::radians(double(state.range(0)) / 10.0);
  auto sun_at = [&](double azimuth_deg) {
    double a = glm::radians(azimuth_deg);
    return enu * glm::dvec3(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
  };
  // A sphere stands in for atmosphere space: Earth's ellipsoid scaled is
  // within 0.3 % of it, which changes no cost.
  const double radius = body.shape.equatorial_radius;
  double patch_ms = 0, shadow_ms = 0;
  int turn = 0;
  for (auto _ : state) {
    auto t0 = std::chrono::steady_clock::now();
    SunShadowField field;
    field.update(surface, glm::dvec3(1.0), radius, camera.pos_body, sun_at(295.0));
    auto t1 = std::chrono::steady_clock::now();
    field.update(surface, glm::dvec3(1.0), radius, camera.pos_body, sun_at(296.0 + turn++));
    auto t2 = std::chrono::steady_clock::now();
    patch_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
    shadow_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
  }
  const double n = double(state.iterations());
  state.counters["new_patch_ms"] = patch_ms / n;
  state.counters["sun_moved_ms"] = shadow_ms / n;
}
BENCHMARK(BM_TerrainShadowField)->Arg(10)->Arg(50)->Arg(200)->Unit(benchmark::kMillisecond);

// The terrain's shadow in the air at 1280x720: 3000 m over the Alps facing
// a sun 1.5 deg up in the west-north-west (hillaire, 4x MSAA), with it off
// (range(0) 0) and on (1). The sun moves a tenth of a degree each frame,
// so that the field and the froxels are computed every frame, as a
// capture's are: their passes' wall time, and the whole frame's.
void BM_TerrainShadowsInAir(benchmark::State& state) {
  auto context = GlContext::create_headless();
  Body body = earth();
  FrameRenderer renderer(1280, 720);
  FrameOptions options;
  options.antialiasing = 4;
  options.synchronous_timing = true;
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body),
                    make_technique(state.range(0) ? "hillaire" : "hillaire:terrain_shadows=off"));
  Geodesy geodesy(body.shape);
  const Geodetic place{glm::radians(46.52), glm::radians(7.95), 3000.0};
  Camera camera = geodesy.camera_at(place, glm::radians(295.0), glm::radians(-3.0),
                                    glm::radians(60.0));
  int turn = 0;
  auto sun = [&] {
    return geodesy.body_direction(place, glm::radians(1.5), glm::radians(300.0 + 0.1 * turn++));
  };
  set_terrain_wait(renderer, 300.0);
  renderer.render(camera, sun(), 10.0);  // builds the tiles, pays for shader compilation
  set_terrain_wait(renderer, 0.0);
  time_frames(state, [&] { return renderer.render(camera, sun(), 10.0); },
              {{"terrain_shadow_ms", {"terrain_shadow"}},
               {"aerial_perspective_ms", {"aerial_perspective"}},
               {"sky_ms", {"sky"}}});
}
BENCHMARK(BM_TerrainShadowsInAir)
    ->Arg(0)
    ->Arg(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// A frame over Earth from range(0) metres, with range(1) samples a pixel
// of anti-aliasing (1: none) and the terrain's shadows when range(2) is 1;
// every pass's wall time with the GL idle around it: the surfaces
// (multisampled), the anti-aliasing's own passes (the resolve and the
// edges), and the whole frame. The sun stands 8 degrees high, where
// shadows are long.
void BM_TerrainFrame(benchmark::State& state) {
  auto context = GlContext::create_headless();
  Body body = earth();
  AtmosphereModel model = load_atmosphere(body);
  FrameRenderer renderer(1280, 720);
  FrameOptions options;
  options.antialiasing = int(state.range(1));
  options.synchronous_timing = true;
  options.terrain_shadows = state.range(2) != 0;
  renderer.set_options(options);
  renderer.set_body(body, model, make_technique("raymarch"));
  Camera camera = camera_above(body, renderer.terrain()->surface(), double(state.range(0)));
  Geodesy geodesy(body.shape);
  glm::dvec3 sun = geodesy.body_from_enu(geodesy.geodetic_from_body(camera.pos_body)) *
                   glm::normalize(glm::dvec3(0.3, -0.95, 0.14));
  set_terrain_wait(renderer, 300.0);
  renderer.render(camera, sun, 8.0);  // builds the tiles, pays for shader compilation
  set_terrain_wait(renderer, 0.0);
  time_frames(state, [&] { return renderer.render(camera, sun, 8.0); },
              {{"surface_ms", {"surface"}}, {"antialias_ms", {"resolve", "antialias"}}});
  state.counters["tiles_drawn"] = renderer.terrain_stats().tiles_drawn;
  state.counters["triangles"] = double(renderer.terrain_stats().triangles);
}
BENCHMARK(BM_TerrainFrame)
    ->ArgsProduct({{2, 10000, 400000}, {1, 4}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// The night sky at 1280x720 (alps_nightfall's last frame: 3200 m over the
// Alps, the sun 19 deg down, hillaire): the whole frame without stars and
// at a fixed exposure (range(0) 0), and with the stars and the automatic
// exposure (1), with their own two passes' wall time.
void BM_StarsFrame(benchmark::State& state) {
  auto context = GlContext::create_headless();
  Body body = earth();
  FrameRenderer renderer(1280, 720);
  FrameOptions options;
  options.antialiasing = 4;
  options.synchronous_timing = true;
  options.stars = state.range(0) != 0;
  options.auto_exposure = state.range(0) != 0;
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body), make_technique("hillaire"));
  Geodesy geodesy(body.shape);
  Camera camera = geodesy.camera_at({glm::radians(46.55), glm::radians(7.98), 3200.0},
                                    glm::radians(115.0), glm::radians(12.0), glm::radians(70.0));
  const UtcSeconds utc = parse_utc("2026-01-15T18:00:00Z", "bench");
  const glm::dvec3 sun = sun_dir_body(body.ephemeris, body.rotation, utc);
  renderer.set_star_orientation(body_from_icrf(body, utc));
  set_terrain_wait(renderer, 300.0);
  renderer.render(camera, sun, 1e4);  // builds the tiles, pays for shader compilation
  set_terrain_wait(renderer, 0.0);
  time_frames(state, [&] { return renderer.render(camera, sun, 1e4); },
              {{"stars_ms", {"stars"}}, {"exposure_ms", {"exposure"}}});
}
BENCHMARK(BM_StarsFrame)
    ->Arg(0)
    ->Arg(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// Earth's imagery at 1280x720 (hillaire, 4x MSAA): 400 km over the
// Mediterranean looking south over Tunisia, the sun 40 deg up (range(1)
// 0) or 30 deg down (1), with the day and night images (range(0) 1) or
// with the palette's colours alone (0): the surfaces' pass and the frame.
void BM_EarthImageryFrame(benchmark::State& state) {
  auto context = GlContext::create_headless();
  Body body = earth();
  if (state.range(0) == 0) body.terrain.erase("maps");
  FrameRenderer renderer(1280, 720);
  FrameOptions options;
  options.antialiasing = 4;
  options.synchronous_timing = true;
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body), make_technique("hillaire"));
  Geodesy geodesy(body.shape);
  const Geodetic place{glm::radians(38.0), glm::radians(11.0), 400e3};
  Camera camera = geodesy.camera_at(place, glm::radians(180.0), glm::radians(-45.0),
                                    glm::radians(60.0));
  glm::dvec3 sun = geodesy.body_direction(place, glm::radians(state.range(1) ? -30.0 : 40.0),
                                          glm::radians(200.0));
  set_terrain_wait(renderer, 300.0);
  renderer.render(camera, sun, 3.0);  // builds the tiles, pays for shader compilation
  set_terrain_wait(renderer, 0.0);
  time_frames(state, [&] { return renderer.render(camera, sun, 3.0); },
              {{"surface_ms", {"surface"}}});
}
BENCHMARK(BM_EarthImageryFrame)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// The world a pilot sees, the whole frame before and after it (1280x720,
// hillaire): range(1) 0 draws as the frame did before it, with no
// anti-aliasing, no shadows on the ground or in the air, no imagery, no
// stars and a fixed exposure; 1 with all of them (4x MSAA). range(0)
// picks the view: 0, alps_sunset's frame 20 (3000 m over the Alps at
// 19:00 UTC, the sun 3 deg up behind); 1, mars_crater_sunset's frame 20
// (4500 m over the crater, the sun 10 deg up behind); 2,
// earth_night_lights' frame 0 (Europe's night side from 400 km). The clock
// moves a minute every frame, so that the sun-dependent passes run every
// frame, as in a capture. What tiles hold (crater marks, coastlines) is
// built once, outside the frames.
void BM_PilotsWorldFrame(benchmark::State& state) {
  struct View {
    const char* body;
    Geodetic place;
    double heading_deg, pitch_deg;
    const char* utc;
    double exposure;
  };
  const View views[] = {
      {"earth", {glm::radians(46.52), glm::radians(7.95), 3000.0}, 100.0, -8.0,
       "2026-06-21T19:00:00Z", 10.0},
      {"mars", {glm::radians(-3.82), glm::radians(137.55), 4500.0}, 105.0, -12.0,
       "2026-06-21T22:30:00Z", 24.0},
      {"earth", {glm::radians(50.0), glm::radians(10.0), 400e3}, 180.0, -60.0,
       "2026-06-21T23:00:00Z", 3.0},
  };
  const View& view = views[state.range(0)];
  const bool after = state.range(1) != 0;
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / (std::string(view.body) + ".json"));
  if (!after) body.terrain.erase("maps");
  FrameRenderer renderer(1280, 720);
  FrameOptions options;
  options.antialiasing = after ? 4 : 1;
  options.synchronous_timing = true;
  options.terrain_shadows = after;
  options.stars = after;
  options.auto_exposure = after;
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body),
                    make_technique(after ? "hillaire" : "hillaire:terrain_shadows=off"));
  Geodesy geodesy(body.shape);
  Camera camera = geodesy.camera_at(view.place, glm::radians(view.heading_deg),
                                    glm::radians(view.pitch_deg), glm::radians(60.0));
  UtcSeconds utc = parse_utc(view.utc, "bench");
  auto frame = [&] {
    renderer.set_star_orientation(body_from_icrf(body, utc));
    FrameStats stats =
        renderer.render(camera, sun_dir_body(body.ephemeris, body.rotation, utc), view.exposure);
    utc += 60.0;
    return stats;
  };
  set_terrain_wait(renderer, 300.0);
  frame();  // builds the tiles, pays for shader compilation
  set_terrain_wait(renderer, 0.0);
  time_frames(state, frame,
              {{"surface_ms", {"surface"}},
               {"antialias_ms", {"resolve", "antialias"}},
               {"terrain_shadow_ms", {"terrain_shadow"}},
               {"aerial_perspective_ms", {"aerial_perspective"}},
               {"sky_ms", {"sky", "space"}},
               {"stars_ms", {"stars"}},
               {"exposure_ms", {"exposure"}}});
}
BENCHMARK(BM_PilotsWorldFrame)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// Earth's clouds at 480x270 under hillaire (range(0): 0 from 500 m over
// the sea, 1 inside the layer at 3 km, 2 from 400 km), the sun 35 deg up,
// at the default quality (range(1) 0) or a cheap one (1: 16 steps, 2
// toward the sun, 4 octaves, marched at one pixel in 16): the clouds pass's wall time against the
// sky's (hillaire's sky and space passes) in the same frames, and their
// ratio (docs/clouds.md#cost).
void BM_CloudsFrame(benchmark::State& state) {
  auto context = GlContext::create_headless();
  Body body = earth();
  FrameRenderer renderer(480, 270);
  FrameOptions options;
  options.antialiasing = 4;
  options.synchronous_timing = true;
  options.clouds = true;
  if (state.range(1) == 1) options.cloud_quality = {16, 2, 4, 4};
  renderer.set_options(options);
  renderer.set_body(body, load_atmosphere(body), make_technique("hillaire"));
  Geodesy geodesy(body.shape);
  const double heights[3] = {500.0, 3000.0, 400e3};
  const double pitches[3] = {10.0, 0.0, -45.0};
  const Geodetic place{glm::radians(30.0), glm::radians(-40.0), heights[state.range(0)]};
  Camera camera = geodesy.camera_at(place, glm::radians(60.0),
                                    glm::radians(pitches[state.range(0)]), glm::radians(70.0));
  const glm::dvec3 sun = geodesy.body_direction(place, glm::radians(35.0), glm::radians(120.0));
  set_terrain_wait(renderer, 300.0);
  renderer.render(camera, sun, 2.0);  // builds the tiles, pays for shader compilation
  set_terrain_wait(renderer, 0.0);
  time_frames(state, [&] { return renderer.render(camera, sun, 2.0); },
              {{"clouds_ms", {"clouds"}}, {"sky_ms", {"sky", "space"}}});
  state.counters["clouds_over_sky"] = state.counters["clouds_ms"] / state.counters["sky_ms"];
}
BENCHMARK(BM_CloudsFrame)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
}  // namespace planet
