// The hillaire technique at 1280x720: the wall time of each pass (the GL
// idle before and after it) on
// the Earth ground, 400 km and 40 000 km views, and in the same run:
//  - the same technique computing every pass every frame (reuse_passes
//    off: how every frame ran before passes were reused), as the ratio
//    every_pass_over_hillaire;
//  - the brute-force per-pixel march (the raymarch technique) of the same
//    image with the same step counts, as raymarch_over_hillaire;
//  - one full-screen write of the HDR target (fill_wall_ms), and the whole
//    sky's passes against it (sky_over_fill).
// Manual time is hillaire's atmosphere passes with reuse; the counters hold
// each pass's mean (ms) and how many passes a frame reused.
#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/gpu/raymarch/raymarch_technique.h"
#include "apps/bench/bench_place.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "gl/fullscreen_pass.h"
#include "gl/program.h"
#include "gl/timer.h"
#include "render/frame.h"
#include "sim/geodesy.h"

#include <benchmark/benchmark.h>
#include <glm/gtc/constants.hpp>

#include <map>
#include <set>

namespace planet {
namespace {

struct BenchView {
  Geodetic place;
  double heading_deg, pitch_deg, fov_deg;
};

// Passes that are not the atmosphere's.
bool is_atmosphere_pass(const std::string& pass) { return pass != "surface" && pass != "tonemap"; }

// The wall time of one full-screen pass that writes a constant into an
// RGBA32F target the size of the frame's HDR target: the least a sky pass
// can cost.
double fill_wall_ms(int width, int height, int frames) {
  Texture target = make_texture_2d(GL_RGBA32F, width, height);
  Framebuffer fbo = make_framebuffer(target.id(), 0);
  Program program = Program::graphics("gl/shaders/fullscreen.vert", "apps/bench/fill.frag");
  FullscreenPass pass;
  GpuTimer timer;
  timer.set_synchronous(true);
  double total = 0;
  for (int i = 0; i <= frames; ++i) {
    timer.begin("fill");
    pass.begin(fbo.id(), width, height, program);
    pass.draw();
    timer.end();
    double ms = timer.collect().front().wall_ms;
    if (i > 0) total += ms;  // the first pays for compiling
  }
  return total / frames;
}

void BM_HillaireSky(benchmark::State& state, BenchView view) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / "earth.json");
  AtmosphereModel model = load_atmosphere(body);
  HillaireTechnique::Settings settings, every_pass;
  every_pass.reuse_passes = false;
  FrameRenderer hillaire(1280, 720), recompute(1280, 720), brute_force(1280, 720);
  hillaire.set_body(body, model, std::make_unique<HillaireTechnique>(settings));
  // Every time here is the passes' wall time, the GL idle before and after
  // each: llvmpipe's timer queries miss much of a scissored pass (from
  // 40 000 km they gave 11 ms for a sky of 107 ms).
  FrameOptions options;
  options.synchronous_timing = true;
  for (FrameRenderer* r : {&hillaire, &recompute, &brute_force}) r->set_options(options);
  recompute.set_body(body, model, std::make_unique<HillaireTechnique>(every_pass));
  // The same steps per pixel as hillaire's per-pixel path, and the
  // transmittance LUT's 40 toward the sun.
  brute_force.set_body(
      body, model,
      std::make_unique<RaymarchTechnique>(RaymarchTechnique::Steps{settings.per_pixel_steps, 40}));
  Geodesy geodesy(body.shape);
  Camera camera = geodesy.camera_at(above_ground(body, view.place), glm::radians(view.heading_deg),
                                    glm::radians(view.pitch_deg), glm::radians(view.fov_deg));
  glm::dvec3 sun = geodesy.body_from_enu(view.place) * glm::normalize(glm::dvec3(0.3, 0.5, 0.6));
  // The first frames pay for llvmpipe's shader compilation (and hillaire's
  // for the model's tables); not timed.
  hillaire.render(camera, sun, 10.0);
  recompute.render(camera, sun, 10.0);
  brute_force.render(camera, sun, 10.0);
  auto atmosphere_ms = [](const FrameStats& stats) {
    double ms = 0;
    for (const PassTiming& p : stats.passes) {
      if (is_atmosphere_pass(p.pass)) ms += p.wall_ms;
    }
    return ms;
  };
  // The view's own tables when recomputed every frame, as in a moving view.
  std::map<std::string, double> pass_ms, recomputed_ms;
  double hillaire_ms = 0, recompute_ms = 0, brute_force_ms = 0, reused = 0;
  for (auto _ : state) {
    FrameStats stats = hillaire.render(camera, sun, 10.0);
    for (const PassTiming& p : stats.passes) {
      if (p.skipped || !is_atmosphere_pass(p.pass)) continue;
      pass_ms[p.pass] += p.wall_ms;
      reused += p.reused ? 1 : 0;
    }
    double ms = atmosphere_ms(stats);
    hillaire_ms += ms;
    FrameStats every = recompute.render(camera, sun, 10.0);
    recompute_ms += atmosphere_ms(every);
    for (const PassTiming& p : every.passes) {
      if (p.pass == "space_view_lut" || p.pass == "sky_view_lut") recomputed_ms[p.pass] += p.wall_ms;
    }
    brute_force_ms += atmosphere_ms(brute_force.render(camera, sun, 10.0));
    state.SetIterationTime(ms * 1e-3);
  }
  double n = double(state.iterations());
  for (const auto& [pass, ms] : pass_ms) state.counters[pass + "_ms"] = ms / n;
  state.counters["passes_reused"] = reused / n;
  for (const auto& [pass, ms] : recomputed_ms) state.counters["every_frame_" + pass + "_ms"] = ms / n;
  state.counters["every_pass_ms"] = recompute_ms / n;
  state.counters["every_pass_over_hillaire"] = recompute_ms / std::max(hillaire_ms, 1e-9);
  state.counters["raymarch_ms"] = brute_force_ms / n;
  state.counters["raymarch_over_hillaire"] = brute_force_ms / std::max(hillaire_ms, 1e-9);
  double fill = fill_wall_ms(1280, 720, 3);
  state.counters["fill_wall_ms"] = fill;
  state.counters["sky_over_fill"] = hillaire_ms / n / std::max(fill, 1e-9);
}

// Looking 10 degrees up from 2 m over the Alps' ground; at the limb from
// 400 km; straight down on the whole disk from 40 000 km (heights above
// the ground: bench_place.h).
BENCHMARK_CAPTURE(BM_HillaireSky, ground,
                  BenchView{{glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0, 60.0})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_HillaireSky, orbit_400km,
                  BenchView{{glm::radians(46.5), glm::radians(8.0), 400e3}, 0.0, -18.0, 60.0})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_HillaireSky, far_40000km,
                  BenchView{{glm::radians(46.5), glm::radians(8.0), 40000e3}, 0.0, -90.0, 30.0})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// A model change in hillaire: the three tables that depend on the model
// alone (transmittance, the orders' multiple-scattering LUT, the glow's
// forward gain), recomputed in the frame after set_atmosphere, each pass's
// wall time (the GL idle before and after it). Manual time is their sum:
// against BrunetonPrecompute/default in the same run, the model
// change ratio.
//
//   planet bench --benchmark_filter='HillaireModelChange|BrunetonPrecompute/default'
void BM_HillaireModelChange(benchmark::State& state) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / "earth.json");
  AtmosphereModel model = load_atmosphere(body);
  FrameRenderer renderer(320, 180);
  FrameOptions options;
  options.synchronous_timing = true;
  renderer.set_options(options);
  renderer.set_body(body, model, std::make_unique<HillaireTechnique>());
  Geodesy geodesy(body.shape);
  const Geodetic place = above_ground(body, {glm::radians(46.5), glm::radians(8.0), 2.0});
  Camera camera = geodesy.camera_at(place, 0.0, glm::radians(10.0), glm::radians(60.0));
  glm::dvec3 sun = geodesy.body_from_enu(place) * glm::normalize(glm::dvec3(0.3, 0.5, 0.6));
  renderer.render(camera, sun, 10.0);  // compiles; not timed
  const std::set<std::string> model_passes = {"transmittance_lut", "multiple_scattering_lut",
                                              "forward_gain_lut"};
  // The view's own tables when recomputed every frame, as in a moving view.
  std::map<std::string, double> pass_ms, recomputed_ms;
  double scale = 1.0;
  for (auto _ : state) {
    // A model no table holds yet: the scattering a millionth stronger.
    scale *= 1.000001;
    renderer.set_atmosphere(with_scattering_scaled(model, scale));
    FrameStats stats = renderer.render(camera, sun, 10.0);
    double ms = 0;
    for (const PassTiming& p : stats.passes) {
      if (!model_passes.count(p.pass) || p.reused) continue;
      pass_ms[p.pass] += p.wall_ms;
      ms += p.wall_ms;
    }
    state.SetIterationTime(ms * 1e-3);
  }
  for (const auto& [pass, ms] : pass_ms) {
    state.counters[pass + "_ms"] = ms / double(state.iterations());
  }
}
BENCHMARK(BM_HillaireModelChange)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace planet
