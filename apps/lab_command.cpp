// planet lab run: the sweep of techniques x quality points x canonical
// scenes (lab/sweep.h), its tables, and the charts and report drawn from
// them by scripts/lab_report.py.
#include "apps/commands.h"
#include "apps/reference_progress.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/progress.h"
#include "gl/context.h"
#include "lab/reference_cache.h"
#include "lab/sweep.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace planet::apps {

namespace {

struct LabArgs {
  SweepOptions options;
  std::string out = "out/lab", paths;
  bool quiet = false, no_report = false;
};

std::filesystem::path report_script() { return project_root() / "scripts" / "lab_report.py"; }

// The python that draws the charts: the first of the PATH's python3 and
// the system's (a python of one's own on the PATH may not see Debian's
// python3-matplotlib) that imports matplotlib. Said before any work.
std::string report_python() {
  check_readable_file(report_script());
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    std::string probe = fmt::format("{} -c 'import matplotlib' > /dev/null 2>&1", python);
    if (std::system(probe.c_str()) == 0) return python;
  }
  throw InputError(
      "lab run: the charts need python3 with matplotlib (Debian's python3-matplotlib; "
      "scripts/install-deps.sh installs it), or --no-report for the tables alone");
}

// The scenes' references and their first orders, rendered first where
// none is cached, after saying what each will cost.
void ensure_references(const SweepPlan& plan, const LabArgs& args) {
  for (const Scene& scene : plan.scenes) {
    reference_for_command(scene, sweep_reference_budget(args.options, scene), args.quiet);
    Scene first = first_order_scene(scene);
    reference_for_command(first, sweep_reference_budget(args.options, first), args.quiet);
  }
}

void run_lab(LabArgs& args) {
  set_progress_shown(!args.quiet);
  SweepOptions& o = args.options;
  o.out = args.out;
  if (!args.paths.empty()) o.paths = PathBudget::parse(args.paths);
  // Every input before any work: names, sizes, the folder, the tools.
  SweepPlan plan = plan_sweep(o);
  std::string python = args.no_report ? "" : report_python();
  OutputFolder folder(o.out, "--out");
  auto context = GlContext::create_headless();
  InterruptScope interrupt;
  ensure_references(plan, args);
  const int total = int(plan.scenes.size() * plan.points.size());
  std::printf("lab: %zu scenes x %zu (technique, quality) points = %d cells into %s\n",
              plan.scenes.size(), plan.points.size(), total, o.out.string().c_str());
  std::fflush(stdout);
  Progress progress("lab run", total, "cell", args.quiet);
  std::vector<SweepCell> cells = run_sweep(o, plan, [&](int done, int, const std::string&) {
    progress.update(done);
    if (interrupt.interrupted()) {
      progress.finish();
      folder.keep();
      std::fprintf(stderr,
                   "planet: interrupted: %d of %d cells are done and kept in %s; run the same "
                   "command again to go on\n",
                   done, total, (o.out / "cells").string().c_str());
      std::exit(kInterruptedExitStatus);
    }
  });
  progress.finish();
  folder.keep();
  int on_front = 0, kept = 0;
  for (const SweepCell& c : cells) on_front += c.on_front ? 1 : 0, kept += c.kept ? 1 : 0;
  std::printf("lab: %zu cells (%zu timed now, %d kept from before), %d on their scene's front; "
              "wrote %s and %s\n",
              cells.size(), cells.size() - size_t(kept), kept, on_front,
              (o.out / "results.json").string().c_str(), (o.out / "results.csv").string().c_str());
  std::fflush(stdout);
  if (args.no_report) return;
  std::string command =
      fmt::format("{} '{}' '{}'", python, report_script().string(), o.out.string());
  if (std::system(command.c_str()) != 0) {
    throw InputError(fmt::format("lab run: {} failed: the tables are in {}, the charts and the "
                                 "report are not",
                                 report_script().string(), o.out.string()));
  }
}

}  // namespace

void add_lab_command(CLI::App& app) {
  CLI::App* lab = app.add_subcommand("lab", "The lab: speed charted against accuracy");
  lab->require_subcommand(1);
  auto args = std::make_shared<LabArgs>();
  CLI::App* run = lab->add_subcommand(
      "run",
      "Time and measure every (technique, quality point, scene) cell, and chart the Pareto fronts");
  run->footer(
      "Cells are kept one file each under OUT/cells as they finish: a sweep stopped part-way "
      "(Ctrl-C) goes on where it stopped, and never times a finished cell again unless --redo. "
      "Writes OUT/results.json, OUT/results.csv, and with python3-matplotlib the charts "
      "(OUT/pareto_*.png, .svg) and OUT/report.html.");
  run->add_option("--techniques", args->options.techniques,
                  "Techniques (default: every one in `planet techniques`)");
  run->add_option("--quality", args->options.qualities,
                  "Quality points (default: each technique's every one, `planet techniques`)");
  run->add_option("--scenes", args->options.scenes,
                  "Canonical scenes (default: every one with an atmosphere)");
  run->add_option("--out", args->out, "Output folder")->capture_default_str();
  run->add_option("--frames", args->options.frames, "Timed frames per cell, after one untimed")
      ->capture_default_str();
  run->add_option("--time-width", args->options.time_width, "Width the cells are timed at")
      ->check(CLI::Range(8, 8192))
      ->capture_default_str();
  run->add_option("--time-height", args->options.time_height, "Height the cells are timed at")
      ->check(CLI::Range(8, 8192))
      ->capture_default_str();
  run->add_option("--width", args->options.width, "Width the cells are measured at")
      ->check(CLI::Range(4, 4096))
      ->capture_default_str();
  run->add_option("--height", args->options.height, "Height the cells are measured at")
      ->check(CLI::Range(2, 4096))
      ->capture_default_str();
  run->add_option("--spp", args->paths,
                  "References' paths per pixel (default: the best cached or shipped, else 8192)");
  run->add_flag("--redo", args->options.redo, "Time and measure finished cells again");
  run->add_flag("--no-report", args->no_report, "The tables alone: no charts, no report");
  run->add_flag("--quiet", args->quiet, "No progress lines");
  run->callback([args] { run_lab(*args); });
}

}  // namespace planet::apps
