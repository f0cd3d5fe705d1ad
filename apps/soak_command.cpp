// planet soak: a long simulated flight over every body, switching bodies
// and techniques, that fails if memory, GL objects or the terrain's tiles
// grow (render/soak.h).
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "atmosphere/gpu/registry.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/progress.h"
#include "gl/context.h"
#include "render/soak.h"
#include "sim/body.h"

#include <fmt/format.h>

#include <cstdio>
#include <memory>

namespace planet::apps {

namespace {

struct SoakArgs {
  SoakOptions options;
  std::string out_dir;
  double terrain_cache_mib = 64;
  bool quiet = false;
};

void run(SoakArgs& args) {
  SoakOptions& o = args.options;
  o.terrain_cache_bytes = size_t(args.terrain_cache_mib * 1048576.0);
  // Every input before GL starts.
  for (const std::string& b : o.bodies) load_body(find_body_file(b));
  for (const std::string& t : o.techniques) parse_technique(t);
  const int legs = o.cycles * int(o.bodies.size());
  if (o.cycles <= o.warmup_cycles) {
    throw InputError(fmt::format("soak: --cycles {} leaves no round after --warmup-cycles {}",
                                 o.cycles, o.warmup_cycles));
  }
  if (o.frames / legs < 2 * int(o.techniques.size())) {
    throw InputError(fmt::format(
        "soak: --frames {} over --cycles {} of {} bodies gives {} frames a body; {} techniques "
        "need at least {}",
        o.frames, o.cycles, o.bodies.size(), o.frames / legs, o.techniques.size(),
        2 * o.techniques.size()));
  }
  std::optional<OutputFolder> out;
  if (!args.out_dir.empty()) out.emplace(args.out_dir, "--out");
  set_progress_shown(!args.quiet);
  auto context = GlContext::create_headless();
  if (!args.quiet) {
    std::fprintf(stderr, "planet: soak of %d frames, %dx%d, %d rounds over %zu bodies on %s\n",
                 o.frames, o.width, o.height, o.cycles, o.bodies.size(),
                 context->renderer().c_str());
  }
  Progress progress("soak", o.frames, "frame", args.quiet);
  InterruptScope interrupt;
  SoakResult r = run_soak(
      o, [&](int done, int, const std::string&) { progress.update(done); },
      [&] { return interrupt.interrupted(); });
  progress.finish();
  if (out) {
    write_file_atomically(std::filesystem::path(args.out_dir) / "soak.json",
                          r.to_json().dump(2) + "\n");
    out->keep();
  }
  if (r.interrupted) {
    std::fprintf(stderr, "planet: soak interrupted after %.0f s; nothing judged\n", r.wall_seconds);
    std::exit(kInterruptedExitStatus);
  }
  std::printf(
      "soak: %d frames in %.0f s; resident memory: warm-up (%d frames) peak %.1f MiB; after it "
      "start %.1f, peak %.1f, end %.1f; GL objects %ld -> %ld (peak %ld), of them outside the tile cache %ld "
      "(peak %ld); terrain tiles peak %.1f of %.1f MiB\n",
      o.frames, r.wall_seconds, r.warmup_frames, r.rss_warmup_peak_mib, r.rss_start_mib, r.rss_peak_mib, r.rss_end_mib,
      r.gl_start.total(), r.gl_end.total(), r.gl_peak.total(), r.gl_fixed_start, r.gl_fixed_peak,
      r.tiles_peak_mib, r.tiles_budget_mib);
  if (!r.failures.empty()) {
    throw SystemError(fmt::format("soak: {}{}", r.failures.front(),
                                  r.failures.size() > 1
                                      ? fmt::format(" (and {} more in soak.json)", r.failures.size() - 1)
                                      : std::string()));
  }
}

}  // namespace

void add_soak_command(CLI::App& app) {
  auto args = std::make_shared<SoakArgs>();
  CLI::App* cmd = app.add_subcommand(
      "soak",
      "Fly each body from the ground to orbit and back, round after round, switching techniques; "
      "fail if memory, GL objects or terrain tiles grow after the warm-up rounds");
  SoakOptions& o = args->options;
  cmd->add_option("--frames", o.frames, "Frames in all (default 10000)")
      ->check(within(8, 10000000));
  cmd->add_option("--cycles", o.cycles, "Rounds over the bodies, the warm-up's included")
      ->check(within(2, 100000));
  cmd->add_option("--warmup-cycles", o.warmup_cycles,
                  "The first rounds, which fill caches and shape the heap (default 2)")
      ->check(within(1, 100000));
  cmd->add_option("--width", o.width, "Frame width")->check(within(8, 4096));
  cmd->add_option("--height", o.height, "Frame height")->check(within(8, 4096));
  add_list_option(*cmd, "--bodies", o.bodies, body_option_help("Bodies in turn, names or files"));
  add_list_option(*cmd, "--techniques", o.techniques, "Techniques in turn on each body with air");
  cmd->add_option("--terrain-cache-mib", args->terrain_cache_mib,
                  "Terrain tiles kept resident, MiB")
      ->check(within(8.0, 65536.0));
  cmd->add_option("--sample-every", o.sample_every, "Frames between samples of memory")
      ->check(within(1, 100000));
  cmd->add_option("--out", args->out_dir, "Folder for soak.json (every sample); none by default");
  cmd->add_flag("--quiet", args->quiet, "Print nothing but the result and errors");
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
