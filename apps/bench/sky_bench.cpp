// Every atmosphere technique of the registry on the same views (the ground,
// 10 km, 400 km and 40 000 km over Earth, Mars and the asteroid), at
// 640x360: GPU time from timer queries, the median of the timed frames, per
// pass (counters, ms) and in total (manual time, the atmosphere's passes:
// the surface and the tone map are the frame's, not the technique's), and
// the technique's cost as a ratio to raymarch on the same view in the same
// run. Each pass waits for the GL before and after it, so that its time is
// its own, and its wall time is kept too (wall_ms, wall_over_raymarch; the
// whole frame's in frame_wall_ms): on llvmpipe the timer queries leave out
// the vertex shaders, which run in the calling thread. The tables a technique computes once per
// model (Bruneton's precompute) are made before timing; their cost is the precompute's, reported by
// the technique itself.
//
//   planet bench --benchmark_filter=^Sky/
//   planet bench --benchmark_filter='^Sky/.*/mars_'
//   planet bench --benchmark_filter=^SkyQuality/    (every quality point, Earth ground)
//   planet bench --benchmark_filter=^SkyHd/         (every technique, Earth ground, 1280x720)
#include "apps/bench/bench_place.h"
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace planet {
namespace {

constexpr int kWidth = 640, kHeight = 360;
constexpr int kTimedFrames = 5;

struct SkyView {
  const char* name;
  double altitude_m;
  double pitch_deg, fov_deg;
};

// Looking 10 degrees up from 2 m, at the horizon from 10 km, at the limb
// from 400 km (18 degrees down reaches past Earth's limb; on the smaller
// bodies the limb is further down and the view holds more sky), and straight
// down on the whole disk from 40 000 km.
const SkyView kViews[] = {
    {"ground", 2.0, 10.0, 60.0},
    {"10km", 10e3, 0.0, 60.0},
    {"400km", 400e3, -18.0, 60.0},
    {"40000km", 40000e3, -90.0, 30.0},
};
const char* const kBodies[] = {"earth", "mars", "asteroid"};

bool is_atmosphere_pass(const std::string& pass) { return pass != "surface" && pass != "tonemap"; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Timed {
  double total_ms = 0;                    // median over the timed frames, atmosphere passes only
  double wall_ms = 0;                     // the same, wall time of the synchronous passes
  double frame_wall_ms = 0;               // every pass of the frame, wall time
  std::map<std::string, double> pass_ms;  // median per pass
  std::map<std::string, double> pass_wall_ms;
};

// The raymarch baseline per body and view, measured when first asked.
std::map<std::string, Timed>& raymarch_baseline() {
  static std::map<std::string, Timed> timed;
  return timed;
}

Timed time_frames(FrameRenderer& renderer, const Camera& camera, const glm::dvec3& sun) {
  // The first frame pays for llvmpipe's shader compilation and the
  // model's tables; not timed.
  renderer.render(camera, sun, 10.0);
  std::vector<double> totals, walls, frame_walls;
  std::map<std::string, std::vector<double>> passes, pass_walls;
  for (int i = 0; i < kTimedFrames; ++i) {
    double total = 0, wall = 0, frame_wall = 0;
    for (const PassTiming& p : renderer.render(camera, sun, 10.0).passes) {
      frame_wall += p.wall_ms;
      if (p.skipped || !is_atmosphere_pass(p.pass)) continue;
      passes[p.pass].push_back(p.gpu_ms);
      pass_walls[p.pass].push_back(p.wall_ms);
      total += p.gpu_ms;
      wall += p.wall_ms;
    }
    totals.push_back(total);
    walls.push_back(wall);
    frame_walls.push_back(frame_wall);
  }
  Timed timed;
  timed.total_ms = median(totals);
  timed.wall_ms = median(walls);
  timed.frame_wall_ms = median(frame_walls);
  for (auto& [pass, ms] : passes) timed.pass_ms[pass] = median(ms);
  for (auto& [pass, ms] : pass_walls) timed.pass_wall_ms[pass] = median(ms);
  return timed;
}

void BM_Sky(benchmark::State& state, std::string technique, std::string body_name, SkyView view,
            int width, int height) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / (body_name + ".json"));
  AtmosphereModel model = load_atmosphere(body);
  Geodesy geodesy(body.shape);
  const Geodetic place =
      above_ground(body, {glm::radians(46.5), glm::radians(8.0), view.altitude_m});
  Camera camera =
      geodesy.camera_at(place, 0.0, glm::radians(view.pitch_deg), glm::radians(view.fov_deg));
  glm::dvec3 sun = geodesy.body_from_enu(place) * glm::normalize(glm::dvec3(0.3, 0.5, 0.6));

  std::string key = fmt::format("{}/{}/{}x{}", body_name, view.name, width, height);
  if (!raymarch_baseline().count(key)) {
    FrameRenderer baseline(width, height);
    FrameOptions options;
    options.synchronous_timing = true;
    baseline.set_options(options);
    baseline.set_body(body, model, make_technique("raymarch"));
    // Timed twice, the second kept: llvmpipe compiles a shader's variants
    // for the GL's state as it first meets them, and in the process's first
    // frames that took 945 ms of a 289 ms frame at the Earth ground view,
    // which skewed every ratio there.
    time_frames(baseline, camera, sun);
    raymarch_baseline()[key] = time_frames(baseline, camera, sun);
  }
  const Timed& raymarch = raymarch_baseline()[key];
  FrameRenderer renderer(width, height);
  FrameOptions options;
  options.synchronous_timing = true;
  renderer.set_options(options);
  renderer.set_body(body, model, make_technique(technique));
  Timed timed;
  for (auto _ : state) {
    timed = time_frames(renderer, camera, sun);
    state.SetIterationTime(timed.total_ms * 1e-3);
  }
  for (const auto& [pass, ms] : timed.pass_ms) state.counters[pass + "_ms"] = ms;
  for (const auto& [pass, ms] : timed.pass_wall_ms) state.counters[pass + "_wall_ms"] = ms;
  state.counters["raymarch_ms"] = raymarch.total_ms;
  state.counters["over_raymarch"] = timed.total_ms / std::max(raymarch.total_ms, 1e-9);
  state.counters["wall_ms"] = timed.wall_ms;
  state.counters["wall_over_raymarch"] = timed.wall_ms / std::max(raymarch.wall_ms, 1e-9);
  state.counters["frame_wall_ms"] = timed.frame_wall_ms;
}

}  // namespace

// One benchmark per (technique, body, view), raymarch's first so that the
// others' ratios reuse its times: Sky/<technique>/<body>_<view>. Registered
// when `planet bench` starts, not at static initialisation, where the
// registry's tables may not be built yet.
void register_sky_benchmarks() {
  std::vector<std::string> names = technique_names();
  std::stable_partition(names.begin(), names.end(),
                        [](const std::string& n) { return n == "raymarch"; });
  for (const char* body : kBodies) {
    for (const SkyView& view : kViews) {
      for (const std::string& technique : names) {
        std::string name = "Sky/" + technique + "/" + body + "_" + view.name;
        benchmark::RegisterBenchmark(name.c_str(), BM_Sky, technique, std::string(body), view,
                                     kWidth, kHeight)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1);
      }
    }
  }
  // Every quality point of every technique on the Earth ground view:
  // SkyQuality/<technique>:<point>/earth_ground.
  for (const TechniqueEntry& entry : technique_registry()) {
    for (const auto& point : entry.quality_points) {
      std::string technique = entry.name + ":" + point.first;
      std::string name = "SkyQuality/" + technique + "/earth_ground";
      benchmark::RegisterBenchmark(name.c_str(), BM_Sky, technique, std::string("earth"), kViews[0],
                                   kWidth, kHeight)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
  }
  // Every technique's whole frame from the ground at 1280x720, the size of
  // Bruneton's demo (../shared/anchors times his own): SkyHd/<technique>.
  for (const std::string& technique : names) {
    std::string name = "SkyHd/" + technique + "/earth_ground";
    benchmark::RegisterBenchmark(name.c_str(), BM_Sky, technique, std::string("earth"), kViews[0],
                                 1280, 720)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
}

}  // namespace planet
