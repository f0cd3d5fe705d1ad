// planet accuracy: a GPU technique against the path-traced ground truth on
// canonical scenes, as a table of RMSE and relative RMSE per channel (sun
// disk left out), with the reference's own noise estimated beside it and taken
// out of the error (with its 95 % interval), the
// relative RMSE over the open sky alone, and the mean signed error (bias);
// the images are written where a person can look at them.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/reference_progress.h"
#include "atmosphere/gpu/registry.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/progress.h"
#include "core/tone_map.h"
#include "gl/context.h"
#include "lab/accuracy.h"
#include "lab/debiased_error.h"
#include "lab/gpu/scene_render.h"
#include "lab/reference_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace planet::apps {

namespace {

// What a reference gets when --spp is not given and none of the view is in
// the cache: about a minute a scene at 32x16 on two cores.
constexpr int kDefaultPaths = 4096;

struct AccuracyArgs {
  std::string technique = "hillaire", out;
  std::vector<std::string> scenes;
  std::string paths;            // empty: the best cached reference, else kDefaultPaths
  int width = 32, height = 16;  // the shipped references' size
  int max_order = 0;            // the ground truth's orders: 0 all
  bool quiet = false;
};

void run_accuracy(const AccuracyArgs& args) {
  set_progress_shown(!args.quiet);
  // Every input before any work: the technique, the scenes, the paths.
  try {
    parse_technique(args.technique);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--technique: {}", e.what()));
  }
  std::vector<Scene> scenes;
  for (const Scene& s : args.scenes.empty() ? canonical_scenes() : std::vector<Scene>{}) {
    if (scene_body(s).has_atmosphere()) scenes.push_back(s);
  }
  for (const auto& name : args.scenes) scenes.push_back(find_scene(name));
  std::optional<PathBudget> given;
  if (!args.paths.empty()) given = PathBudget::parse(args.paths);
  std::vector<PathBudget> budgets;
  for (Scene& scene : scenes) {
    scene.width = args.width;
    scene.height = args.height;
    scene.max_order = checked_max_order(args.max_order, "accuracy --max-order");
    scene_atmosphere(scene, scene_body(scene));  // an airless scene fails here
    std::optional<PathBudget> cached = best_cached_budget(scene, ReferenceMode::kRgb);
    budgets.push_back(given ? *given : cached ? *cached : PathBudget(kDefaultPaths));
    budgets.back().lane_paths(3);
  }
  std::optional<OutputFolder> folder;
  if (!args.out.empty()) folder.emplace(args.out, "--out");
  auto context = GlContext::create_headless();
  // What only a GL context can tell (a table larger than its textures),
  // before the table's header and the first reference.
  try {
    make_technique(parse_technique(args.technique));
  } catch (const InputError& e) {
    throw InputError(fmt::format("--technique: {}", e.what()));
  }
  std::printf("%-16s %-3s %11s %11s %9s %9s %-24s %9s %6s\n", "scene", "ch", "RMSE", "mean ref",
              "rel RMSE", "ref noise", " debiased (95 % interval)", "sky only", "bias");
  InterruptScope interrupt;
  for (size_t k = 0; k < scenes.size(); ++k) {
    const Scene& scene = scenes[k];
    const PathBudget& budget = budgets[k];
    ReferenceRender ground_truth = reference_for_command(scene, budget, args.quiet);
    const ImageRGB& reference = ground_truth.image;
    ImageRGB technique = render_scene_with(scene, args.technique);
    TechniqueAccuracy accuracy = measure_accuracy(scene, technique, reference);
    // The reference's own noise: the RMS of its per-pixel standard error.
    std::array<double, 3> noise = masked_rms(ground_truth.noise, sun_disk_mask(scene));
    // The technique's own error, the reference's noise taken out.
    std::array<DebiasedError, 3> debiased =
        debiased_error(technique, reference, ground_truth.noise, sun_disk_mask(scene));
    const char* names[3] = {"R", "G", "B"};
    for (size_t c = 0; c < 3; ++c) {
      const ChannelError& e = accuracy.channels[c];
      double bias = 0;
      for (size_t i = c; i < accuracy.signed_error.pixels.size(); i += 3) {
        bias += accuracy.signed_error.pixels[i];
      }
      bias /= double(std::max(accuracy.pixels, 1));
      const DebiasedError& d = debiased[c];
      std::string interval =
          fmt::format("{:8.2f}% [{:.2f}, {:.2f}]", 100 * d.relative(d.debiased_rmse),
                      100 * d.relative(d.low), 100 * d.relative(d.high));
      std::printf("%-16s %-3s %11.4g %11.4g %8.2f%% %8.2f%% %-24s %8.2f%% %+5.1f%%\n",
                  scene.name.c_str(), names[c], e.rmse, e.mean_reference, 100 * e.relative(),
                  100 * noise[c] / std::max(e.mean_reference, 1e-30), interval.c_str(),
                  100 * accuracy.sky_channels[c].relative(), 100 * bias);
    }
    if (folder) write_accuracy_images(folder->path(), scene, technique, reference, accuracy);
    std::fflush(stdout);
  }
  if (folder) folder->keep();
}

}  // namespace

void add_accuracy_command(CLI::App& app) {
  auto args = std::make_shared<AccuracyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "accuracy", "Measure an atmosphere technique against the path-traced ground truth");
  cmd->add_option("--technique", args->technique, "Atmosphere technique, NAME[:KEY=VALUE,...]")
      ->capture_default_str();
  add_schedule_option(*cmd);
  add_list_option(*cmd, "--scene", args->scenes,
                  "Canonical scenes (default: all with an atmosphere)");
  cmd->add_option("--spp", args->paths,
                  fmt::format("Reference paths per pixel, in all or per channel (R,G,B) (default: "
                              "the cached reference of the view with the most paths, else {})",
                              kDefaultPaths));
  cmd->add_option("--width", args->width, "Image width")
      ->check(within(1, 4096))
      ->capture_default_str();
  cmd->add_option("--height", args->height, "Image height")
      ->check(within(1, 4096))
      ->capture_default_str();
  cmd->add_option("--max-order", args->max_order,
                  "Measure against the ground truth's first N orders of scattering alone (1: "
                  "single scattering; default: every order)");
  cmd->add_option("--out", args->out, "Folder for technique, reference and error images");
  cmd->add_flag("--quiet", args->quiet, "No progress and no word of references to render");
  cmd->footer(
      fmt::format("References are read from {} and the shipped {}; one in neither is "
                  "rendered into the first, after saying what it costs.",
                  reference_cache_dir().string(), shipped_reference_dir().string()));
  cmd->callback([args] { run_accuracy(*args); });
}

}  // namespace planet::apps
