#include "render/soak.h"

#include "atmosphere/gpu/registry.h"
#include "core/error.h"
#include "gl/driver_watch.h"
#include "render/frame.h"
#include "sim/body.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>

namespace planet {

namespace {

nlohmann::json gl_json(const GlObjectCounts& c) {
  nlohmann::json j;
  for (size_t k = 0; k < kGlObjectKinds; ++k) j[gl_object_kind_name(GlObjectKind(k))] = c.live[k];
  j["total"] = c.total();
  return j;
}

// One visit to a body: its file read again (as a pilot's switch does), its
// atmosphere, its ground's reckoning and the highest point of the flight.
struct Visit {
  Body body;
  std::optional<AtmosphereModel> atmosphere;
  std::unique_ptr<TerrainSurface> surface;
  double top_m = 0;
};

Visit visit(const std::string& name) {
  Visit v;
  v.body = load_body(find_body_file(name));
  if (v.body.has_atmosphere()) v.atmosphere = load_atmosphere(v.body);
  v.surface = std::make_unique<TerrainSurface>(v.body.shape, parse_terrain(v.body));
  // Orbit: a few hundred km over Earth and Mars, well clear of a small body.
  v.top_m = std::max(0.06 * v.body.shape.equatorial_radius, 20e3);
  return v;
}

std::unique_ptr<AtmosphereTechnique> technique_for(const std::string& choice,
                                                   const AtmosphereModel& model) {
  auto t = make_technique(choice);
  t->update(model);
  return t;
}

}  // namespace

double heap_in_use_mib() {
  struct mallinfo2 m = mallinfo2();
  return double(m.uordblks + m.hblkhd) / double(1 << 20);
}

double resident_mib() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  statm >> size >> resident;
  return resident * double(sysconf(_SC_PAGESIZE)) / double(1 << 20);
}

nlohmann::json SoakResult::to_json() const {
  nlohmann::json samples_json = nlohmann::json::array();
  for (const SoakSample& s : samples) {
    samples_json.push_back({{"frame", s.frame},
                            {"body", s.body},
                            {"technique", s.technique},
                            {"height_m", s.height_m},
                            {"rss_mib", s.rss_mib},
                            {"heap_mib", s.heap_mib},
                            {"tiles_mib", s.tiles_mib},
                            {"tiles", s.tiles},
                            {"gl_objects", gl_json(s.gl)}});
  }
  return {{"frames", samples.empty() ? 0 : samples.back().frame + 1},
          {"warmup_frames", warmup_frames},
          {"rss_mib",
           {{"warmup_peak", rss_warmup_peak_mib},
            {"start", rss_start_mib},
            {"peak", rss_peak_mib},
            {"end", rss_end_mib}}},
          {"gl_objects", {{"start", gl_json(gl_start)}, {"peak", gl_json(gl_peak)}, {"end", gl_json(gl_end)}}},
          {"gl_objects_outside_tile_cache", {{"start", gl_fixed_start}, {"peak", gl_fixed_peak}}},
          {"tiles_mib", {{"peak", tiles_peak_mib}, {"budget", tiles_budget_mib}}},
          {"wall_seconds", wall_seconds},
          {"interrupted", interrupted},
          {"held", failures.empty() && !interrupted},
          {"failures", failures},
          {"samples", samples_json}};
}

namespace {

// Where a frame of a leg looks from: `u` of the way along the leg, up from
// 2 m to the top and down again, evenly in the logarithm of the height,
// along the same track every round (a round after the warm-up asks for
// just what the warm-up did, so whatever it holds more is kept, not
// needed).
struct LegView {
  Camera camera;
  glm::dvec3 sun;
  double above_m = 0;  // over the ground
};

LegView leg_view(const Visit& v, const Geodesy& geodesy, double u) {
  double s = 1.0 - std::abs(2.0 * u - 1.0);
  Geodetic place{glm::radians(20.0), glm::radians(20.0 * u), 0.0};
  double ground = ground_height(*v.surface, geodesy, place);
  LegView view;
  view.above_m = 2.0 * std::pow(v.top_m / 2.0, s);
  place.height = ground + view.above_m;
  view.camera =
      geodesy.camera_at(place, glm::radians(360.0 * u), glm::radians(-10.0), glm::radians(60.0));
  view.sun = geodesy.body_direction(place, glm::radians(25.0), glm::radians(140.0));
  return view;
}

// What the soak watches between frames: memory and GL objects sampled
// every few frames and at the end of each round, their peaks in the
// warm-up and after it.
struct SoakWatch {
  double warmup_peak = 0;
  long warmup_gl_fixed_peak = 0;
  std::vector<double> cycle_end_rss;
  std::vector<GlObjectCounts> cycle_end_gl;

  void sample(SoakResult& r, int frame, const std::string& body, const std::string& technique,
              double above_m, const TerrainStats& ts, bool cycle_end) {
    {
      DriverWait wait("finishing a frame of the soak");
      glFinish();
    }
    const double tiles = double(ts.bytes_resident) / double(1 << 20);
    SoakSample s{frame,
                 body,
                 technique,
                 above_m,
                 resident_mib(),
                 heap_in_use_mib(),
                 tiles,
                 ts.tiles_on_gpu,
                 live_gl_objects()};
    const long fixed = s.gl.total() - long(s.tiles);
    if (cycle_end) {
      cycle_end_gl.push_back(s.gl);
      cycle_end_rss.push_back(s.rss_mib);
    }
    if (frame < r.warmup_frames) {
      warmup_peak = std::max(warmup_peak, s.rss_mib);
      warmup_gl_fixed_peak = std::max(warmup_gl_fixed_peak, fixed);
      if (cycle_end) r.gl_fixed_start = fixed;
    } else {
      r.rss_peak_mib = std::max(r.rss_peak_mib, s.rss_mib);
      r.gl_fixed_peak = std::max(r.gl_fixed_peak, fixed);
    }
    r.samples.push_back(s);
  }
};

// After the last round: where the warm-up left memory and GL objects (the
// same phase, the end of a round, as every later round is measured at, and
// the highest it reached), and whether the rounds after it stayed there.
void judge(const SoakOptions& o, const SoakWatch& w, SoakResult& r) {
  const size_t warm = size_t(o.warmup_cycles) - 1;
  r.rss_start_mib = w.cycle_end_rss[warm];
  r.rss_end_mib = w.cycle_end_rss.back();
  r.rss_warmup_peak_mib = w.warmup_peak;
  r.gl_start = w.cycle_end_gl[warm];
  r.gl_end = w.cycle_end_gl.back();
  r.gl_peak = *std::max_element(w.cycle_end_gl.begin(), w.cycle_end_gl.end(),
                                [](const auto& a, const auto& b) { return a.total() < b.total(); });
  const double limit = std::max(r.rss_start_mib, w.warmup_peak) * (1.0 + o.rss_tolerance);
  if (r.rss_peak_mib > limit) {
    r.failures.push_back(fmt::format(
        "resident memory peaked at {:.1f} MiB after the warm-up, over {:.1f} MiB ({:.0f} % above "
        "the warm-up's {:.1f} MiB)",
        r.rss_peak_mib, limit, 100.0 * o.rss_tolerance, std::max(r.rss_start_mib, w.warmup_peak)));
  }
  if (r.rss_end_mib > r.rss_start_mib * (1.0 + o.rss_tolerance)) {
    r.failures.push_back(fmt::format(
        "resident memory at the end of the last round is {:.1f} MiB, {:.1f} % above the {:.1f} "
        "MiB at the end of the warm-up",
        r.rss_end_mib, 100.0 * (r.rss_end_mib / r.rss_start_mib - 1.0), r.rss_start_mib));
  }
  // The tile cache's buffers follow the view within its budget (checked
  // each frame); everything else must come back to where the warm-up left
  // it.
  if (r.gl_fixed_peak > w.warmup_gl_fixed_peak) {
    r.failures.push_back(fmt::format(
        "GL objects outside the terrain's tile cache reached {} after the warm-up, over the {} "
        "they reached in it",
        r.gl_fixed_peak, w.warmup_gl_fixed_peak));
  }
}

}  // namespace

SoakResult run_soak(const SoakOptions& o,
                    const std::function<void(int, int, const std::string&)>& progress,
                    const std::function<bool()>& stop) {
  const int legs = o.cycles * int(o.bodies.size());
  const int leg_frames = o.frames / legs;
  if (o.warmup_cycles < 1 || o.cycles <= o.warmup_cycles ||
      leg_frames < int(o.techniques.size()) * 2) {
    throw InputError(fmt::format(
        "soak: {} frames over {} cycles ({} of warm-up) of {} bodies leave too few frames a leg "
        "or no round after the warm-up",
        o.frames, o.cycles, o.warmup_cycles, o.bodies.size()));
  }
  const int total = leg_frames * legs;
  SoakResult r;
  r.warmup_frames = leg_frames * int(o.bodies.size()) * o.warmup_cycles;
  r.tiles_budget_mib = double(o.terrain_cache_bytes) / double(1 << 20);

  FrameRenderer renderer(o.width, o.height);
  FrameOptions frame_options;
  frame_options.terrain.cache_bytes = o.terrain_cache_bytes;
  frame_options.terrain_wait_s = 60.0;
  renderer.set_options(frame_options);

  auto start = std::chrono::steady_clock::now();
  SoakWatch watch;
  int frame = 0;
  for (int leg = 0; leg < legs && !r.interrupted; ++leg) {
    Visit v = visit(o.bodies[size_t(leg) % o.bodies.size()]);
    Geodesy geodesy(v.body.shape);
    const int segment = leg_frames / int(o.techniques.size());
    int technique_index = -1;
    for (int i = 0; i < leg_frames; ++i, ++frame) {
      if (stop()) {
        r.interrupted = true;
        break;
      }
      // A new technique every `segment` frames (the first with the body).
      int wanted = std::min(i / segment, int(o.techniques.size()) - 1);
      const std::string choice = v.atmosphere ? o.techniques[size_t(wanted)] : "none";
      if (i == 0) {
        renderer.set_body(v.body, v.atmosphere,
                          v.atmosphere ? technique_for(choice, *v.atmosphere) : nullptr);
        technique_index = wanted;
      } else if (v.atmosphere && wanted != technique_index) {
        renderer.swap_technique(technique_for(choice, *v.atmosphere));
        technique_index = wanted;
      }
      LegView view = leg_view(v, geodesy, (i + 0.5) / leg_frames);
      renderer.render(view.camera, view.sun, 1.0);

      const TerrainStats& ts = renderer.terrain_stats();
      double tiles = double(ts.bytes_resident) / double(1 << 20);
      r.tiles_peak_mib = std::max(r.tiles_peak_mib, tiles);
      if (ts.bytes_resident > o.terrain_cache_bytes) {
        r.failures.push_back(fmt::format("frame {}: terrain tiles {:.1f} MiB over the budget of {:.1f}",
                                         frame, tiles, r.tiles_budget_mib));
      }
      bool cycle_end = i == leg_frames - 1 && (leg + 1) % int(o.bodies.size()) == 0;
      if (frame % o.sample_every == 0 || cycle_end) {
        watch.sample(r, frame, v.body.name, choice, view.above_m, ts, cycle_end);
      }
      if (progress) {
        progress(frame + 1, total,
                 fmt::format("{} {} {:.0f} m", v.body.name, choice, view.above_m));
      }
    }
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (r.interrupted || int(watch.cycle_end_rss.size()) <= o.warmup_cycles) return r;
  judge(o, watch, r);
  return r;
}

}  // namespace planet
