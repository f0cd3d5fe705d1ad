// Sky techniques at 1280x720 on the Earth ground view, GPU time per frame
// from timer queries (manual time), so that ratios between techniques are
// measured in one run.
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "gl/timer.h"
#include "render/frame.h"
#include "sim/geodesy.h"

#include <benchmark/benchmark.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <map>
#include <string>

namespace planet {
namespace {

void BM_SkyGround(benchmark::State& state, const char* technique) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / "earth.json");
  AtmosphereModel model = load_atmosphere(body);
  FrameRenderer renderer(1280, 720);
  renderer.set_body(body, model, make_technique(technique));
  Geodesy geodesy(body.shape);
  Geodetic place{glm::radians(46.5), glm::radians(8.0), 2.0};
  Camera camera = geodesy.camera_at(place, 0.0, glm::radians(10.0), Camera().vertical_fov);
  glm::dvec3 sun = geodesy.body_from_enu(place) * glm::normalize(glm::dvec3(0.3, 0.5, 0.6));
  // The first frame pays for llvmpipe's shader compilation; not timed.
  renderer.render(camera, sun, 10.0);
  std::map<std::string, double> pass_ms;
  for (auto _ : state) {
    FrameStats stats = renderer.render(camera, sun, 10.0);
    state.SetIterationTime(stats.total_gpu_ms() * 1e-3);
    for (const PassTiming& p : stats.passes) pass_ms[p.pass] += p.gpu_ms;
  }
  // Each pass's mean, so that the atmosphere's share is read apart from
  // the surfaces' (the same for every technique).
  for (const auto& [name, ms] : pass_ms) {
    state.counters[name + "_ms"] = ms / double(std::max<int64_t>(state.iterations(), 1));
  }
}
BENCHMARK_CAPTURE(BM_SkyGround, raymarch, "raymarch")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SkyGround, oneil, "oneil")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace planet
