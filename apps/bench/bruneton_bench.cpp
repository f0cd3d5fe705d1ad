// The bruneton technique's precompute for Earth, computed afresh (into a
// cache folder of its own, removed after): the whole update's wall time
// (manual time: the shaders' compiles, the orders and the cache's write),
// the orders' sum (orders_s) and each order (order_1_s holds the
// transmittance and direct irradiance with single scattering), at three
// quality points.
//
//   planet bench --benchmark_filter=BrunetonPrecompute
#include "atmosphere/gpu/bruneton/bruneton_technique.h"
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <string>

namespace planet {
namespace {

void BM_BrunetonPrecompute(benchmark::State& state, const char* quality) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / "earth.json");
  AtmosphereModel model = load_atmosphere(body);
  std::filesystem::path cache = std::filesystem::temp_directory_path() / "planet-bench-bruneton";
  const char* before = std::getenv("PLANET_CACHE_DIR");
  std::string kept = before ? before : "";
  setenv("PLANET_CACHE_DIR", cache.c_str(), 1);
  std::vector<double> seconds;
  double update_seconds = 0.0;
  for (auto _ : state) {
    std::filesystem::remove_all(cache);
    // The whole model change, as Bruneton's Model::Init is timed: the
    // shaders' compiles, the orders and the cache's write.
    auto began = std::chrono::steady_clock::now();
    auto technique = make_technique(parse_technique(std::string("bruneton:") + quality));
    technique->update(model);
    update_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    seconds = static_cast<BrunetonTechnique&>(*technique).precompute_seconds();
    state.SetIterationTime(update_seconds);
  }
  std::filesystem::remove_all(cache);
  if (before) {
    setenv("PLANET_CACHE_DIR", kept.c_str(), 1);
  } else {
    unsetenv("PLANET_CACHE_DIR");
  }
  state.counters["orders_s"] = std::accumulate(seconds.begin(), seconds.end(), 0.0);
  for (size_t i = 0; i < seconds.size(); ++i) {
    state.counters["order_" + std::to_string(i + 1) + "_s"] = seconds[i];
  }
}

BENCHMARK_CAPTURE(BM_BrunetonPrecompute, cheap, "cheap")
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_BrunetonPrecompute, bruneton2017, "bruneton2017")
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_BrunetonPrecompute, default, "default")
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace planet
