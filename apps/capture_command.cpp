// planet capture: a scripted flight rendered headless into EXR + PNG frames.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/progress.h"
#include "gl/context.h"
#include "governor/governor.h"
#include "render/capture.h"
#include "render/capture_shares.h"
#include "sim/flight_script.h"
#include "terrain/ground.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace planet::apps {

namespace {

struct CaptureArgs {
  std::string flight_file, out_dir, frames, shard;
  std::vector<std::string> merge;
  bool quiet = false;
  double pixel_budget = 1.0;
  double terrain_cache_mib = 256.0;
  double error_budget = std::nan("");  // NaN: none given
  std::string error_model;
  bool glare = false;
  bool pass_table = false;
  // In place of the script's own (render/capture_overrides.h).
  std::optional<std::string> technique;
  std::optional<int> width, height;
  std::optional<double> scale;
};

// "1 frame", "41 frames".
std::string count_of(int n, const char* thing) {
  return fmt::format("{} {}{}", n, thing, n == 1 ? "" : "s");
}

// "A:B" (B exclusive), "A:" or ":B".
std::pair<int, int> parse_frame_range(const std::string& text) {
  auto colon = text.find(':');
  if (colon == std::string::npos) {
    throw InputError(fmt::format("--frames '{}': expected A:B (B exclusive)", text));
  }
  auto parse = [&](const std::string& s, int fallback) {
    if (s.empty()) return fallback;
    size_t used = 0;
    int v = -1;
    try {
      v = std::stoi(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || v < 0) {
      throw InputError(fmt::format("--frames '{}': '{}' is not a frame number", text, s));
    }
    return v;
  };
  return {parse(text.substr(0, colon), 0), parse(text.substr(colon + 1), -1)};
}

// Frames of an earlier, longer capture removed from the folder, and why.
void print_removed(const FramesBeyond& removed, const std::string& out_dir) {
  if (removed.count == 0) return;
  std::printf(
      "removed %s beyond the flight's end from %s (frames %d to %d, an earlier capture's)\n",
      count_of(removed.count, "frame").c_str(), out_dir.c_str(), removed.first, removed.last);
}

// The shares' frames put together into --out, every share checked first.
void run_merge(const CaptureArgs& args) {
  if (args.out_dir.empty()) throw InputError("capture --merge: --out is required");
  if (!args.flight_file.empty() || !args.frames.empty() || !args.shard.empty()) {
    throw InputError(
        "capture --merge: the shares say what they are of; give only --merge "
        "DIR... and --out");
  }
  std::vector<std::filesystem::path> inputs(args.merge.begin(), args.merge.end());
  MergedCapture merged = merge_capture_shares(inputs, args.out_dir);
  if (args.quiet) return;
  std::printf("merged %s of %s (%.1f s of capture) into %s\n",
              count_of(merged.frames, "frame").c_str(), count_of(merged.shares, "share").c_str(),
              merged.wall_seconds, args.out_dir.c_str());
  print_removed(merged.removed, args.out_dir);
}

void run(const CaptureArgs& args) {
  if (!args.merge.empty()) {
    run_merge(args);
    return;
  }
  if (args.flight_file.empty()) throw InputError("capture: --flight is required");
  // The ground under the keyframes, for those given above it and the
  // checks below: the body's terrain, read once.
  GroundHeight ground = terrain_ground();
  FlightScript script = load_flight_script(args.flight_file, ground);
  if (args.glare) script.glare = true;
  CaptureOptions options;
  options.overrides.technique = args.technique;
  options.overrides.width = args.width;
  options.overrides.height = args.height;
  options.overrides.scale = args.scale;
  apply_capture_overrides(script, options.overrides);
  options.out_dir = args.out_dir.empty() ? std::filesystem::path("out") / script.name
                                         : std::filesystem::path(args.out_dir);
  if (!args.frames.empty()) {
    std::tie(options.first_frame, options.end_frame) = parse_frame_range(args.frames);
  }
  if (!args.shard.empty()) {
    if (!args.frames.empty()) {
      throw InputError("capture: --shard picks its own frames; give --shard or --frames");
    }
    options.share = parse_share(args.shard, "--shard");
    std::tie(options.first_frame, options.end_frame) = capture_share_frames(script, options.share);
    options.out_dir = capture_share_dir(capture_shares_dir(options.out_dir), options.share);
  }
  options.progress = !args.quiet;
  set_progress_shown(!args.quiet);
  options.pixel_budget = args.pixel_budget;
  options.pass_table = args.pass_table;
  options.terrain_cache_bytes = size_t(args.terrain_cache_mib * 1048576.0);
  // Every input, and the output folder, before GL starts.
  if (!std::isnan(args.error_budget)) {
    options.error_budget_percent = checked_error_budget(args.error_budget, "--error-budget");
  }
  options.error_model_file = args.error_model;
  const CapturePlan plan = plan_capture(script, options);
  const std::optional<double> budget = plan.budget;
  if (options.error_budget_percent && args.technique && !args.quiet) {
    std::fprintf(stderr, "planet: --technique %s wins over --error-budget: the governor is off\n",
                 args.technique->c_str());
  } else if (options.error_budget_percent && script.technique_named && !args.quiet) {
    std::fprintf(stderr,
                 "planet: %s names its technique (%s), which wins over --error-budget: the "
                 "governor is off\n",
                 script.file.string().c_str(), script.technique.c_str());
  }
  check_keyframes_above_ground(script, ground);
  OutputFolder out(options.out_dir, "--out");
  auto context = GlContext::create_headless();
  if (!args.quiet) {
    // Where the first frame starts, both ways a script gives heights.
    Geodetic start = FlightPath(script).place_at(script.frame_time(options.first_frame));
    std::string sky = !script.body.has_atmosphere() ? "no atmosphere"
                      : budget ? fmt::format("governed sky (budget {:g} %)", *budget)
                               : script.technique + " sky";
    std::fprintf(stderr,
                 "planet: %s, %dx%d, %s at %g fps, %s on %s; frame %d at %.1f m above the "
                 "ellipsoid, %.1f m above the ground\n",
                 script.body.name.c_str(), script.width, script.height,
                 count_of(script.frame_count(), "frame").c_str(), script.frame_rate, sky.c_str(),
                 context->renderer().c_str(), options.first_frame, start.height,
                 start.height - ground(script.body, start));
  }
  CaptureResult result;
  try {
    result = run_capture(script, options, plan);
  } catch (const CaptureInterrupted& e) {
    out.keep();  // its complete frames
    std::fprintf(stderr, "planet: %s\n", e.what());
    // std::exit unwinds no stack: the context goes first, or the driver's
    // memory for it is left behind (LeakSanitizer's report).
    context.reset();
    std::exit(130);  // as a shell reports a program stopped by SIGINT
  }
  out.keep();
  // Asked for, the table is printed even when quiet.
  if (args.pass_table) {
    std::printf("each pass, its mean wall and GPU time over the frames it ran:\n%s",
                result.passes.table().c_str());
  }
  if (args.quiet) return;
  std::printf("captured %s in %.1f s into %s (first %s, last %s)\n",
              count_of(result.frames, "frame").c_str(), result.wall_seconds,
              options.out_dir.string().c_str(), result.first_png.filename().string().c_str(),
              result.last_png.filename().string().c_str());
  // Frames earlier runs left (the run this one resumes, the slices before):
  // capture.json describes them all.
  if (result.folder.first != plan.first || result.folder.end != plan.end) {
    std::printf("%s holds frames %d to %d of %d, whole (%.1f s of capture, the runs' together)\n",
                options.out_dir.string().c_str(), result.folder.first, result.folder.end - 1,
                script.frame_count(), result.folder.wall_seconds);
  }
  print_removed(result.removed, options.out_dir.string());
}

}  // namespace

void add_capture_command(CLI::App& app) {
  auto args = std::make_shared<CaptureArgs>();
  CLI::App* cmd =
      app.add_subcommand("capture", "Render a scripted flight headless into EXR + PNG frames");
  cmd->add_option("--flight", args->flight_file, "Flight script (data/flights/*.json); required");
  cmd->add_option("--out", args->out_dir, "Output folder (default out/<flight name>)");
  cmd->add_option("--frames", args->frames, "Slice of frames A:B to render (B exclusive)");
  cmd->add_option("--shard", args->shard,
                  "Render share K of N (from 0) of the frames, for a cluster, into "
                  "<--out>.shares/share-K-of-N");
  cmd->add_option("--merge", args->merge,
                  "Put the shares in these folders together into the capture folder --out")
      ->expected(1, -1);
  cmd->add_flag("--quiet", args->quiet, "Print nothing but errors");
  cmd->add_flag("--glare", args->glare,
                "The eye's glare around the sun, as fly draws it (the flight's \"image\": "
                "{\"glare\": true})");
  cmd->add_flag("--pass-table", args->pass_table,
                "At the end, each pass's mean wall and GPU time and how often it ran, was "
                "reused or skipped (each pass then waits for the GL)");
  cmd->add_option("--pixel-budget", args->pixel_budget,
                  "Terrain detail: largest projected geometric error in pixels")
      ->check(within(0.1, 100.0));
  cmd->add_option("--terrain-cache-mib", args->terrain_cache_mib,
                  "Terrain tiles kept resident, MiB")
      ->check(within(8.0, 65536.0));
  cmd->add_option("--error-budget", args->error_budget,
                  "Let the governor choose each frame's technique: the cheapest whose predicted "
                  "error is within PCT percent (a technique the script names wins)");
  cmd->add_option("--error-model", args->error_model,
                  "The governor's table (default data/lab/error_model.json)");
  cmd->add_option("--technique", args->technique,
                  "Atmosphere technique name[:key=value,...], in place of the script's (wins "
                  "over --error-budget)");
  add_schedule_option(*cmd);
  cmd->add_option("--width", args->width,
                  "Image width in pixels, in place of the script's (alone: the height keeps the "
                  "script's aspect)");
  cmd->add_option("--height", args->height,
                  "Image height in pixels, in place of the script's (alone: the width keeps the "
                  "script's aspect)");
  cmd->add_option("--scale", args->scale,
                  "Scale the script's image size by this (0.25: a quarter the width and height)");
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
