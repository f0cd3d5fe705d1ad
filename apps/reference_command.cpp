// planet reference: the path-traced ground truth of a canonical scene, as
// linear EXR (and a tone-mapped PNG beside it), through the reference cache.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/progress.h"
#include "core/tone_map.h"
#include "lab/accuracy.h"
#include "lab/reference_cache.h"
#include "lab/reference_merge.h"
#include "lab/reference_share.h"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace planet::apps {

namespace {

struct ReferenceArgs {
  std::string scene, out, mode = "rgb";
  std::string paths = "256";
  std::string shard;
  std::vector<std::string> merge;
  int width = 0, height = 0;
  int max_order = 0;
  bool list = false, quiet = false;
};

// Share K of N of the render, into the shares folder beside --out.
void run_share(const ReferenceArgs& args, const Scene& scene, const PathBudget& budget,
               ReferenceMode mode, const Share& share) {
  std::filesystem::path out(args.out);
  OutputFolder folder(reference_shares_dir(out), "--out");
  remove_stale_partials(reference_shares_dir(out));
  double pixels = double(scene.width) * scene.height;
  double share_paths = budget.spp * std::ceil(pixels / share.count);
  Progress progress(fmt::format("reference {} share {}", scene.name, share.label()), share_paths,
                    "path", args.quiet);
  InterruptScope interrupt;
  auto start = std::chrono::steady_clock::now();
  ReferenceShareRender render;
  try {
    render = render_reference_share(
        scene, budget, mode, share, out, [&](double done) { progress.update(done * share_paths); },
        &InterruptScope::flag());
  } catch (const ReferenceInterrupted& e) {
    progress.finish();
    folder.keep();
    std::fprintf(stderr, "planet: %s\n", e.what());
    std::exit(kInterruptedExitStatus);
  }
  progress.finish();
  folder.keep();
  if (args.quiet) return;  // errors alone
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: share %s, %dx%d, %s spp, %s: %.0f paths in %.1f s into %s\n", scene.name.c_str(),
              share.label().c_str(), scene.width, scene.height, budget.label().c_str(),
              to_string(mode), double(render.paths), seconds, render.file.string().c_str());
}

// The shares put together into --out, checked whole before anything is
// written.
void run_merge(const ReferenceArgs& args) {
  std::vector<std::filesystem::path> inputs(args.merge.begin(), args.merge.end());
  std::filesystem::path out(args.out);
  OutputFolder folder(out.has_parent_path() ? out.parent_path() : ".", "--out");
  auto start = std::chrono::steady_clock::now();
  MergedReference merged = merge_reference_shares(inputs);
  std::filesystem::path png = std::filesystem::path(out).replace_extension(".png");
  write_exr(out, merged.render.image);
  write_tone_mapped_png(png, merged.render.image, merged.scene.exposure);
  folder.keep();
  // The merge is done once its files are written; a cache that cannot
  // take it (a node's read-only home) is worth a word, not a failed job.
  std::string cached;
  try {
    cached = cache_merged_reference(merged).string();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "planet: the merged reference is not cached: %s\n", e.what());
    cached = "not written";
  }
  if (args.quiet) return;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %dx%d, %s spp, %s, merged from %d shares in %.2f s\n", merged.scene.name.c_str(),
              merged.scene.width, merged.scene.height, merged.paths.label().c_str(),
              to_string(merged.mode), merged.shares, seconds);
  std::printf("wrote %s and %s (exposure %g); cache %s\n", out.string().c_str(),
              png.string().c_str(), merged.scene.exposure, cached.c_str());
}

void run_reference(const ReferenceArgs& args) {
  set_progress_shown(!args.quiet);
  if (!args.merge.empty()) {
    if (args.out.empty()) throw InputError("reference --merge: --out is required");
    if (!args.scene.empty() || !args.shard.empty()) {
      throw InputError(
          "reference --merge: the shares say their scene and budget; give only "
          "--merge DIR... and --out");
    }
    run_merge(args);
    return;
  }
  if (args.list) {
    for (const Scene& s : canonical_scenes()) {
      std::printf("%-22s %-9s %s\n", s.name.c_str(), s.body.c_str(), s.description.c_str());
    }
    std::printf("and, apart from the canonical table, the eclipse scenes:\n");
    for (const Scene& s : eclipse_scenes()) {
      std::printf("%-22s %-9s %s\n", s.name.c_str(), s.body.c_str(), s.description.c_str());
    }
    return;
  }
  if (args.scene.empty() || args.out.empty()) {
    throw InputError("reference: --scene and --out are required (--list shows the scenes)");
  }
  // Every input, and where the image goes, before the render.
  Scene scene = find_scene(args.scene);
  if (args.width > 0) scene.width = args.width;
  if (args.height > 0) scene.height = args.height;
  scene.max_order = checked_max_order(args.max_order, "reference --max-order");
  ReferenceMode mode = parse_reference_mode(args.mode);
  PathBudget budget = PathBudget::parse(args.paths);
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  budget.lane_paths(make_medium(model, mode).channels.size());
  if (!args.shard.empty()) {
    run_share(args, scene, budget, mode, parse_share(args.shard, "--shard"));
    return;
  }
  std::filesystem::path out(args.out);
  const std::filesystem::path out_dir = out.has_parent_path() ? out.parent_path() : ".";
  OutputFolder folder(out_dir, "--out");
  remove_stale_partials(out_dir);
  std::filesystem::path cached = reference_cache_file(scene, model, budget, mode);
  bool was_cached = reference_cached(scene, budget, mode);
  if (!was_cached && !args.quiet) {
    RenderCost cost = estimate_reference_cost(scene, budget, mode);
    std::fprintf(stderr, "planet: %s\n",
                 describe_uncached_reference(scene, budget, mode, cost).c_str());
  }
  auto start = std::chrono::steady_clock::now();
  double pixels = double(scene.width) * scene.height;
  Progress progress("reference " + scene.name, pixels * budget.spp, "path", args.quiet);
  InterruptScope interrupt;
  ReferenceRender render;
  bool first = true;
  auto on_progress = [&](double done) {
    if (first) progress.begin_at(done * pixels * budget.spp);  // what it goes on from
    first = false;
    progress.update(done * pixels * budget.spp);
  };
  try {
    render = reference_render(scene, budget, mode, on_progress, &InterruptScope::flag());
  } catch (const ReferenceInterrupted& e) {
    progress.finish();
    std::fprintf(stderr, "planet: %s\n", e.what());
    std::exit(kInterruptedExitStatus);
  }
  progress.finish();
  const ImageRGB& image = render.image;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_exr(out, image);
  std::filesystem::path png = std::filesystem::path(out).replace_extension(".png");
  write_tone_mapped_png(png, image, scene.exposure);
  folder.keep();
  if (args.quiet) return;  // errors alone
  double traced = pixels * budget.spp * (1.0 - render.started_share);
  std::string orders = scene.max_order > 0 ? fmt::format(", orders 1 to {}", scene.max_order) : "";
  std::printf("%s: %dx%d, %s spp, %s%s, %s in %.1f s (%.3g paths/s)\n", scene.name.c_str(),
              scene.width, scene.height, budget.label().c_str(), args.mode.c_str(), orders.c_str(),
              was_cached ? "from the cache" : "rendered", seconds,
              was_cached ? 0.0 : traced / seconds);
  if (!render.started_from.empty()) {
    std::printf("went on from %s (%.1f%% of the paths)\n", render.started_from.string().c_str(),
                100 * render.started_share);
  }
  // The render's own noise: the RMS of its per-pixel standard error over
  // the mean radiance, sun disk excluded, as `planet accuracy` gives it.
  std::vector<uint8_t> mask = sun_disk_mask(scene);
  std::array<double, 3> noise = masked_rms(render.noise, mask), mean = masked_mean(image, mask);
  std::printf("noise (standard error, RMS over the mean): R %.3f%% G %.3f%% B %.3f%%\n",
              100 * noise[0] / mean[0], 100 * noise[1] / mean[1], 100 * noise[2] / mean[2]);
  std::printf("wrote %s and %s (exposure %g); cache %s\n", out.string().c_str(),
              png.string().c_str(), scene.exposure, cached.string().c_str());
}

}  // namespace

void add_reference_command(CLI::App& app) {
  auto args = std::make_shared<ReferenceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "reference", "Path-trace a canonical scene's ground truth (cached, see --help)");
  cmd->footer(
      fmt::format("Renders are cached by a hash of model, scene, spp, mode and tracer "
                  "version in {}. A render writes its running sums there every few "
                  "minutes (.sums): run it again and it goes on from them, and a "
                  "larger --spp for the same view starts from the sums of a smaller "
                  "one.",
                  reference_cache_dir().string()));
  cmd->add_option("--scene", args->scene, "Scene name (see --list); required");
  cmd->add_option("--spp", args->paths,
                  "Paths per pixel: in all (98304), or per channel (32768,131072,524288)");
  cmd->add_option("--out", args->out,
                  "Output EXR (a tone-mapped PNG is written beside it); required");
  cmd->add_option("--mode", args->mode, "rgb (the techniques' 3 wavelengths) or spectral");
  cmd->add_option("--width", args->width, "Image width (default: the scene's, 128)")
      ->check(within(1, 8192));
  cmd->add_option("--height", args->height, "Image height (default: the scene's, 64)")
      ->check(within(1, 8192));
  cmd->add_option("--shard", args->shard,
                  "Render share K of N (from 0) of the pixels, for a cluster: its sums go to "
                  "<--out's stem>.shares/share-K-of-N.sums");
  cmd->add_option("--merge", args->merge,
                  "Put the shares in these folders (or files) together into --out, byte for "
                  "byte the render made at once")
      ->expected(1, -1);
  cmd->add_option("--max-order", args->max_order,
                  "Sum only the first N orders of scattering (1: single scattering alone; "
                  "default: every order); cached apart from the full ground truth");
  cmd->add_flag("--list", args->list, "List the canonical scenes and the eclipse scenes");
  cmd->add_flag("--quiet", args->quiet, "Errors alone: no progress, no result lines");
  cmd->callback([args] { run_reference(*args); });
}

}  // namespace planet::apps
