// planet lab clarity: how far the ground shows through the air, by the
// ground truth and every technique (lab/gpu/clarity_run.h).
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/reference_progress.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/progress.h"
#include "gl/context.h"
#include "lab/gpu/clarity_run.h"

#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>

namespace planet::apps {

namespace {

struct ClarityArgs {
  ClarityOptions options;
  std::string out = "out/lab/clarity", paths;
  bool quiet = false;
};

void run_clarity_command(ClarityArgs& args) {
  set_progress_shown(!args.quiet);
  ClarityOptions& o = args.options;
  if (!args.paths.empty()) o.paths = PathBudget::parse(args.paths);
  // Every input before any work: the views, the techniques, the folder.
  clarity_plan(o);
  OutputFolder folder(args.out, "--out");
  auto context = GlContext::create_headless();
  InterruptScope interrupt;
  auto results = run_clarity(o, [&](const Scene& scene) {
    return reference_for_command(scene, o.paths, args.quiet).image;
  });
  std::string text = clarity_text(results);
  std::printf("%s", text.c_str());
  write_file_atomically(folder.path() / "clarity.txt", text);
  write_file_atomically(folder.path() / "clarity.csv", clarity_csv(results));
  folder.keep();
  std::printf("wrote %s and %s\n", (folder.path() / "clarity.txt").string().c_str(),
              (folder.path() / "clarity.csv").string().c_str());
}

}  // namespace

void add_lab_clarity_command(CLI::App& lab) {
  auto args = std::make_shared<ClarityArgs>();
  CLI::App* cmd = lab.add_subcommand(
      "clarity",
      "How far the ground shows through the air: views down from 6 km and 400 km over Earth "
      "and 10 km over Mars, with a target of albedo 0.05 and one of 0.5 where each ray meets "
      "the ground, drawn by the ground truth and every technique; the contrast (L_bright - "
      "L_dark) / (L0_bright - L0_dark) against distance beside the model's transmittance, and "
      "the visibility (the distance at 2 % contrast). Writes OUT/clarity.txt and "
      "OUT/clarity.csv.");
  add_list_option(*cmd, "--views", args->options.views,
                  "Views (default: earth_6km, earth_400km, mars_10km)");
  add_list_option(*cmd, "--techniques", args->options.techniques,
                  "Techniques (NAME or NAME:KEY=VALUE,...; default: every one at its default)");
  add_schedule_option(*cmd);
  cmd->add_option("--spp", args->paths,
                  "The ground truths' paths per pixel (default 4096: shipped in data/reference)");
  cmd->add_option("--ground-paths", args->options.ground_paths,
                  "Paths per row and channel for the ground's own radiance")
      ->capture_default_str();
  cmd->add_flag("--uniform", args->options.uniform,
                "Two uniform grounds of those albedos, not two small targets on the model's "
                "ground");
  cmd->add_option("--out", args->out, "Output folder")->capture_default_str();
  cmd->add_flag("--quiet", args->quiet, "No progress lines");
  cmd->callback([args] { run_clarity_command(*args); });
}

}  // namespace planet::apps
