// The path tracer's speed on Earth noon at 128x64: paths per second on one
// core (items_per_second), in RGB and spectral mode, and on all cores.
#include "atmosphere/reference/reference_render.h"
#include "lab/scene.h"

#include <benchmark/benchmark.h>

namespace planet {
namespace {

void BM_ReferenceEarthNoon(benchmark::State& state, ReferenceMode mode, int threads) {
  Scene scene = find_scene("earth_noon");
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  Medium medium = make_medium(model, mode);
  ReferenceView view = reference_view(scene, body, model);
  ReferenceSettings settings;
  // One path per channel and replicate per pixel: 6 (RGB) or 42 (spectral).
  settings.paths = kReplicates * int(medium.channels.size());
  settings.threads = threads;
  settings.seed = scene.seed();
  int64_t paths = 0;
  for (auto _ : state) {
    ReferenceImage image = render_reference(medium, view, settings);
    benchmark::DoNotOptimize(image.rgb.data());
    paths += int64_t(image.paths);
  }
  state.SetItemsProcessed(paths);
  state.counters["threads"] = threads;
}
BENCHMARK_CAPTURE(BM_ReferenceEarthNoon, rgb_1_core, ReferenceMode::kRgb, 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ReferenceEarthNoon, spectral_1_core, ReferenceMode::kSpectral, 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ReferenceEarthNoon, rgb_2_threads, ReferenceMode::kRgb, 2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace planet
