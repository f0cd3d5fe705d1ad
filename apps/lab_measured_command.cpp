// planet lab measured: the ground truth and every technique against a
// measured day's sky (lab/gpu/measured_run.h), and the report drawn from it by
// lab/report/measured_report.py.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/progress.h"
#include "gl/context.h"
#include "lab/gpu/measured_run.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

namespace planet::apps {

namespace {

struct MeasuredArgs {
  MeasuredOptions options;
  std::string data, out = "out/lab/measured";
  bool quiet = false, no_report = false;
};

std::filesystem::path measured_script() {
  return project_root() / "lab" / "report" / "measured_report.py";
}

void run_measured_command(MeasuredArgs& args) {
  set_progress_shown(!args.quiet);
  MeasuredOptions& o = args.options;
  o.data = args.data.empty() ? project_root() / "data" / "measured" / "kider-2013-05-27"
                             : std::filesystem::path(args.data);
  o.out = args.out;
  // Every input before any work: the captures, the body, the names, the tools.
  MeasuredPlan plan = plan_measured(o);
  std::string python;
  if (!args.no_report) {
    check_readable_file(measured_script());
    python = matplotlib_python("lab measured");
  }
  OutputFolder folder(o.out, "--out");
  auto context = GlContext::create_headless();
  folder.keep();  // the ground truth's cache goes in it from the first capture on
  InterruptScope interrupt;
  std::optional<Progress> progress;
  std::string stage;
  auto rows = run_measured(o, plan, [&](const std::string& label, int done, int total) {
    if (label != stage) {
      if (progress) progress->finish();
      progress.emplace("lab measured: " + label, total,
                       label == "ground truth" ? "direction" : "triple", args.quiet);
      stage = label;
    }
    progress->update(done);
    if (interrupt.interrupted()) {
      // The ground truth's finished captures are on disk, each whole; the
      // workers of the one in progress are left to the exit, which skips
      // the destructors that would wait for them.
      progress->finish();
      std::fprintf(stderr,
                   "planet: interrupted: the ground truth of every finished capture is kept in "
                   "%s; run the same command again to go on from there\n",
                   (o.out / "ground_truth").string().c_str());
      std::fflush(stdout);
      std::_Exit(kInterruptedExitStatus);
    }
  });
  if (progress) progress->finish();
  std::printf("%s", measured_summary(o, plan, rows).c_str());
  std::printf("wrote %s and %s\n", (o.out / "measured.json").string().c_str(),
              (o.out / "measured.csv").string().c_str());
  if (!python.empty()) {
    std::string command =
        fmt::format("{} '{}' '{}'", python, measured_script().string(), o.out.string());
    if (std::system(command.c_str()) != 0) {
      throw InputError(fmt::format("lab measured: {} failed: the tables are in {}, the plots and "
                                   "the report are not",
                                   measured_script().string(), o.out.string()));
    }
    std::printf("wrote %s\n", (o.out / "report.html").string().c_str());
  }
}

}  // namespace

void add_lab_measured_command(CLI::App& lab) {
  auto args = std::make_shared<MeasuredArgs>();
  CLI::App* cmd = lab.add_subcommand(
      "measured",
      "The ground truth and every technique against measured skies (Kider et al. 2014: 81 "
      "directions, 350-830 nm, shipped for 2013-05-27 09:30-11:15): spectral RMSE over "
      "360-720 nm in mW m^-2 sr^-1 nm^-1 and zenith luminance per capture and in total, "
      "beside Bruneton's 2016 evaluation. Writes OUT/measured.json, .csv, summary.txt and, "
      "with python3-matplotlib, the plots and OUT/report.html.");
  cmd->add_option("--data", args->data,
                  "A day's folder of capture folders (default data/measured/kider-2013-05-27)");
  cmd->add_option("--body", args->options.body, "The body preset that models the day")
      ->capture_default_str();
  add_list_option(
      *cmd, "--techniques", args->options.techniques,
      "Techniques (NAME or NAME:KEY=VALUE,...; default: every one at its default; none: "
      "the ground truth alone)");
  add_list_option(*cmd, "--captures", args->options.captures,
                  "Captures by local time, HH:MM (default all)");
  cmd->add_option("--directions", args->options.directions,
                  "Directions per capture, spread over the scan with the zenith (1-81)")
      ->capture_default_str();
  cmd->add_option("--paths", args->options.paths,
                  "Ground truth paths per direction and spectral sample")
      ->capture_default_str();
  cmd->add_flag("--as-recorded", args->options.as_recorded,
                "The scanner's azimuths as recorded, not turned onto the sun's");
  cmd->add_option("--out", args->out, "Output folder")->capture_default_str();
  cmd->add_flag("--no-report", args->no_report, "The tables alone: no plots, no report");
  cmd->add_flag("--quiet", args->quiet, "No progress lines");
  cmd->callback([args] { run_measured_command(*args); });
}

}  // namespace planet::apps
