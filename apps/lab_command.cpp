// planet lab run: the sweep of techniques x quality points x canonical
// scenes (lab/gpu/sweep.h), its tables, and the charts and report drawn from
// them by lab/report/lab_report.py.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/reference_progress.h"
#include "atmosphere/gpu/bruneton/bruneton_cache.h"
#include "core/atomic_file.h"
#include "core/cache_dir.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/job.h"
#include "core/paths.h"
#include "core/progress.h"
#include "core/version.h"
#include "gl/context.h"
#include "lab/gpu/error_model_build.h"
#include "lab/gpu/governor_check.h"
#include "lab/gpu/sweep.h"
#include "lab/reference_cache.h"
#include "lab/stability.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace planet::apps {

namespace {

struct LabArgs {
  SweepOptions options;
  std::string out = "out/lab", paths, error_model;
  bool quiet = false, no_report = false;
};

std::filesystem::path report_script() {
  return project_root() / "lab" / "report" / "lab_report.py";
}

std::string report_python() {
  check_readable_file(report_script());
  return matplotlib_python("lab run");
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

// The bruneton cache keeps every table the sweep reads again where the
// environment sets no limit and the disk has room; else this says what the
// cells will pay. Kept too small, the cache pushes out each scene's tables
// before a later run reads them: every one is computed again.
void keep_sweep_tables(const SweepPlan& plan) {
  const uintmax_t need = sweep_disk_table_bytes(plan);
  const uintmax_t limit = bruneton_cache_limit_bytes();
  if (limit == 0 || need <= limit) return;
  const std::filesystem::path dir = cache_dir("bruneton");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::filesystem::space_info space = std::filesystem::space(dir, ec);
  const bool room = !ec && space.available + bruneton_cache_bytes() >= need;
  auto gb = [](uintmax_t bytes) { return double(bytes) / (1024.0 * 1024.0 * 1024.0); };
  if (room && !bruneton_cache_limit_from_environment()) {
    set_bruneton_cache_floor(need);
    std::printf("lab: its bruneton tables take %.1f GB, over the cache's default %.1f GB: this "
                "run keeps up to %.1f GB in %s\n",
                gb(need), gb(limit), gb(need), dir.string().c_str());
    return;
  }
  std::fflush(stdout);
  std::string advice =
      room ? fmt::format("; set PLANET_BRUNETON_CACHE_MB={:.0f} or more to keep them",
                         std::ceil(double(need) / (1024.0 * 1024.0)))
           : "";
  std::fprintf(stderr,
               "lab: its bruneton tables take %.1f GB, over the %.1f GB that %s: a table pushed "
               "out is computed again before its cell (seconds to minutes each)%s\n",
               gb(need), gb(limit),
               room ? "PLANET_BRUNETON_CACHE_MB keeps" : "the cache's disk has room for",
               advice.c_str());
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
  std::optional<OutputFolder> model_folder;
  if (!args.error_model.empty()) {
    std::filesystem::path file = args.error_model;
    if (std::filesystem::is_directory(file)) {
      throw InputError(fmt::format("--error-model: {} is a folder; give a file, such as "
                                   "data/lab/error_model.json",
                                   file.string()));
    }
    model_folder.emplace(file.has_parent_path() ? file.parent_path() : ".", "--error-model");
    model_folder->keep();
  }
  auto context = GlContext::create_headless();
  JobProgress progress("lab run", "cell", "cells", args.quiet, o.out / "cells",
                       [&] { folder.keep(); });
  ensure_references(plan, args);
  const int total = int(plan.scenes.size() * plan.points.size());
  std::printf("lab: %zu scenes x %zu (technique, quality) points = %d cells into %s\n",
              plan.scenes.size(), plan.points.size(), total, o.out.string().c_str());
  keep_sweep_tables(plan);
  std::fflush(stdout);
  progress.expect_parts(sweep_cell_costs(o, plan));  // the time left by the cells' costs
  std::vector<SweepCell> cells = run_sweep(o, plan, progress.steps());
  progress.finish();
  // The governor's table: the cells, and what a model change costs each choice.
  auto changes = model_change_times(o, plan, [&](const std::string& choice) {
    if (!args.quiet) std::fprintf(stderr, "lab: timing a model change of %s\n", choice.c_str());
    if (progress.interrupted()) {
      folder.keep();
      std::fprintf(stderr, "planet: interrupted: the cells are kept in %s; run the same command "
                           "again to go on\n", o.out.string().c_str());
      std::exit(kInterruptedExitStatus);
    }
  });
  std::string source = fmt::format("planet lab run, planet {}, {} cells timed at {}x{} on {}",
                                   planet_version(), cells.size(), o.time_width, o.time_height,
                                   reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  std::string table = error_model_to_json(build_error_model(cells, changes, o, source)).dump(2) + "\n";
  write_file_atomically(o.out / "error_model.json", table);
  if (!args.error_model.empty()) write_file_atomically(args.error_model, table);
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

struct StabilityArgs {
  StabilityOptions options;
  std::string out = "out/lab/stability", shard = "1/1";
  bool quiet = false, no_report = false, list = false;
};

std::filesystem::path stability_script() {
  return project_root() / "lab" / "report" / "stability_report.py";
}

// What the shard's cells not yet done will cost on this machine, said
// before any of it: the ground truths to render and the techniques' draws.
// The rates are this project's 2-core llvmpipe machine's, from a full
// default sweep (docs/stability.md#the-whole-sweep).
double estimate_stability_seconds(const StabilityOptions& o,
                                  const std::vector<StabilityCell>& cells, int& references,
                                  int& draws) {
  const auto points = stability_points(o.techniques);
  const Job job = stability_job(o, cells);
  std::vector<int> left(cells.size(), 0);
  double seconds = 0;
  references = draws = 0;
  for (const JobCell& draw : job.cells()) {
    if (job.finished(draw)) continue;
    const StabilityCell& cell = cells[draw.index / points.size()];
    const auto& [technique, quality] = points[draw.index % points.size()];
    ++left[draw.index / points.size()];
    // Bruneton's default tables, made once per model: 19 s on average
    // here; any other draw 0.05-0.8 s.
    bool tables = technique == "bruneton" && quality == "default" && cell.point.altitude_m == 2.0 &&
                  cell.point.sun_elevation_deg == 60.0;
    seconds += tables ? 19.0 : 0.4;
    ++draws;
  }
  for (size_t i = 0; i < cells.size(); ++i) {
    PathBudget budget = stability_reference_budget(cells[i]);
    if (left[i] > 0 && !reference_cached(cells[i].scene, budget, ReferenceMode::kRgb)) {
      ++references;
      seconds += stability_reference_seconds(cells[i]);
    }
  }
  return seconds;
}

void run_stability_command(StabilityArgs& args) {
  set_progress_shown(!args.quiet);
  StabilityOptions& o = args.options;
  o.out = args.out;
  std::tie(o.shard, o.shards) = parse_shard(args.shard);
  std::vector<StabilityCell> all = plan_stability(o);
  stability_points(o.techniques);  // an unknown technique or setting fails here, before any work
  if (args.list) {
    for (const StabilityCell& c : all) {
      std::string slices;
      for (const std::string& s : c.slices) slices += (slices.empty() ? "" : " ") + s;
      std::printf("%s  (%s)\n", c.scene.name.c_str(), slices.c_str());
    }
    return;
  }
  std::vector<StabilityCell> cells = shard_cells(named_cells(all, o.cells), o.shard, o.shards);
  std::string python;
  if (!args.no_report) {
    check_readable_file(stability_script());
    python = report_python();
  }
  OutputFolder folder(o.out, "--out");
  int references = 0, draws = 0;
  double seconds = estimate_stability_seconds(o, cells, references, draws);
  std::printf("lab stability: shard %d/%d: %zu of the map's %zu cells x %zu (technique, quality) "
              "points into %s\n",
              o.shard, o.shards, cells.size(), all.size(), stability_points(o.techniques).size(),
              o.out.string().c_str());
  std::printf("lab stability: %d ground truths to render (16x8 and the like: seconds each, a "
              "minute in dense air) and %d draws to make: about %.0f min on this project's 2-core "
              "machine\n",
              references, draws, seconds / 60.0);
  std::fflush(stdout);
  auto context = GlContext::create_headless();
  JobProgress progress("lab stability", "draw", "draws", args.quiet, o.out / "cells",
                       [&] { folder.keep(); });
  std::vector<StabilityResult> results = run_stability(o, cells, progress.steps());
  progress.finish();
  folder.keep();
  std::map<std::string, int> counts;
  for (const StabilityResult& r : results) ++counts[to_string(r.cls)];
  std::string summary;
  for (const char* c : {"ok", "inaccurate", "nan", "exploded", "failed"}) {
    summary += fmt::format("{}{} {}", summary.empty() ? "" : ", ", counts[c], c);
  }
  std::printf("lab stability: %zu results in %s (every shard's there): %s; wrote %s and %s\n",
              results.size(), o.out.string().c_str(), summary.c_str(),
              (o.out / "stability.json").string().c_str(),
              (o.out / "stability.csv").string().c_str());
  std::fflush(stdout);
  if (args.no_report) return;
  std::string command =
      fmt::format("{} '{}' '{}'", python, stability_script().string(), o.out.string());
  if (std::system(command.c_str()) != 0) {
    throw InputError(fmt::format("lab stability: {} failed: the tables are in {}, the maps and "
                                 "the report are not",
                                 stability_script().string(), o.out.string()));
  }
}

struct GovernorArgs {
  GovernorCheckOptions options;
  std::string out = "out/lab/governor", error_model;
  bool quiet = false, canonical_only = false, cached_held_out = false;
};

void run_governor_command(GovernorArgs& args) {
  set_progress_shown(!args.quiet);
  GovernorCheckOptions& o = args.options;
  o.out = args.out;
  o.error_model = args.error_model;
  o.held_out = !args.canonical_only;
  o.render_held_out = !args.cached_held_out;
  check_governor_options(o);
  OutputFolder folder(o.out, "--out");
  if (o.held_out) {
    HeldOutTruths t = held_out_truths(o);
    if (o.render_held_out && t.to_render == 0) {
      std::printf("lab governor: the %d held-out views' ground truths are all cached\n",
                  t.cached);
    } else if (o.render_held_out) {
      std::printf("lab governor: %d held-out views' ground truths cached, %d to render (16x8: "
                  "seconds each, a minute in dense air): about %.0f min on this project's 2-core "
                  "machine\n",
                  t.cached, t.to_render, t.seconds / 60.0);
    } else {
      std::printf("lab governor: the %d held-out views whose ground truth is cached\n", t.cached);
    }
    std::fflush(stdout);
  }
  auto context = GlContext::create_headless();
  JobProgress progress("lab governor", "view", "checks", args.quiet, o.out / "views",
                       [&] { folder.keep(); });
  auto checks = run_governor_check(o, progress.steps());
  progress.finish();
  folder.keep();
  std::string summary = write_governor_check(o, checks);
  std::printf("%swrote %s and %s\n", summary.c_str(), (o.out / "governor.json").string().c_str(),
              (o.out / "governor.csv").string().c_str());
}

}  // namespace

std::string matplotlib_python(const std::string& what) {
  // The first of the PATH's python3 and the system's (a python of one's own
  // on the PATH may not see Debian's python3-matplotlib) that imports it.
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    std::string probe = fmt::format("{} -c 'import matplotlib' > /dev/null 2>&1", python);
    if (std::system(probe.c_str()) == 0) return python;
  }
  throw InputError(fmt::format(
      "{}: the charts need python3 with matplotlib (Debian's python3-matplotlib; "
      "scripts/install-deps.sh installs it), or --no-report for the tables alone",
      what));
}

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
  add_list_option(*run, "--techniques", args->options.techniques,
                  "Techniques (default: every one in `planet techniques`)");
  add_schedule_option(*run);
  add_list_option(*run, "--quality", args->options.qualities,
                  "Quality points (default: each technique's every one, `planet techniques`)");
  add_list_option(*run, "--scenes", args->options.scenes,
                  "Canonical scenes (default: every one with an atmosphere)");
  run->add_option("--out", args->out, "Output folder")->capture_default_str();
  run->add_option("--frames", args->options.frames, "Timed frames per cell, after one untimed")
      ->capture_default_str();
  run->add_option("--time-width", args->options.time_width, "Width the cells are timed at")
      ->check(within(8, 8192))
      ->capture_default_str();
  run->add_option("--time-height", args->options.time_height, "Height the cells are timed at")
      ->check(within(8, 8192))
      ->capture_default_str();
  run->add_option("--width", args->options.width, "Width the cells are measured at")
      ->check(within(4, 4096))
      ->capture_default_str();
  run->add_option("--height", args->options.height, "Height the cells are measured at")
      ->check(within(2, 4096))
      ->capture_default_str();
  run->add_option("--spp", args->paths,
                  "References' paths per pixel (default: the best cached or shipped, else 8192)");
  run->add_option("--error-model", args->error_model,
                  "Also write the governor's table here (data/lab/error_model.json ships it); "
                  "OUT/error_model.json always");
  run->add_flag("--redo", args->options.redo, "Time and measure finished cells again");
  run->add_flag("--no-report", args->no_report, "The tables alone: no charts, no report");
  run->add_flag("--quiet", args->quiet, "No progress lines");
  run->callback([args] { run_lab(*args); });

  auto st = std::make_shared<StabilityArgs>();
  CLI::App* stability = lab->add_subcommand(
      "stability",
      "Where each technique breaks: every technique over one-axis sweeps and two planes around "
      "each body preset, each cell classified against its own ground truth");
  stability->footer(
      "Axes around Earth, Mars and the asteroid: density x0.1-100, Mie g -0.5-0.99, bottom "
      "radius 10 km-70 000 km (at the preset's thickness ratio and at its thickness), scale "
      "heights x0.25-10, camera altitude -1 km (inside the planet) to 1e9 m, sun elevation -20 to "
      "90 deg; planes density x g and bottom radius x altitude. Classes: ok (within the budget), "
      "inaccurate, nan, exploded (a value below zero or over 10x its reference's), failed (an "
      "error or over the time limit). Results are kept one file per draw under OUT/cells: a "
      "sweep stopped part-way goes on where it stopped; --shard K/N runs part K of N, and the "
      "tables and maps gather every shard's results found in OUT. Writes OUT/stability.json, "
      "OUT/stability.csv, and with python3-matplotlib the maps, the line plots and "
      "OUT/report.html.");
  add_list_option(*stability, "--techniques", st->options.techniques,
                  "Techniques (default: every one in `planet techniques`)");
  add_schedule_option(*stability);
  add_list_option(*stability, "--bodies", st->options.bodies,
                  fmt::format("Body presets (default: {})", fmt::join(stability_bodies(), ", ")));
  add_list_option(*stability, "--cells", st->options.cells, "Only these cells, by name (--list)");
  stability->add_flag("--list", st->list, "List the map's cells and their slices, and stop");
  stability->add_option("--out", st->out, "Output folder")->capture_default_str();
  stability->add_option("--budget", st->options.budget_percent,
                        "Error budget, percent: a cell within it is ok")
      ->capture_default_str();
  stability->add_option("--time-limit", st->options.time_limit_s,
                        "Seconds a technique may take over a cell before it counts as failed")
      ->capture_default_str();
  stability->add_option("--width", st->options.width, "Width of each cell's view")
      ->check(within(4, 512))
      ->capture_default_str();
  stability->add_option("--height", st->options.height, "Height of each cell's view")
      ->check(within(2, 256))
      ->capture_default_str();
  stability->add_option("--shard", st->shard, "This machine's part K of N, by cell")
      ->capture_default_str();
  stability->add_flag("--redo", st->options.redo, "Draw and classify finished cells again");
  stability->add_flag("--no-report", st->no_report, "The tables alone: no maps, no report");
  stability->add_flag("--quiet", st->quiet, "No progress lines");
  stability->callback([st] { run_stability_command(*st); });

  auto gv = std::make_shared<GovernorArgs>();
  CLI::App* governor = lab->add_subcommand(
      "governor",
      "Check the governor: on every canonical scene, its choice's error against the ground "
      "truth and its cost against the cheapest that meets the budget in the lab's table; on "
      "views held out of the table (the stability map's one-axis cells, 126 views whose 16x8 "
      "ground truths are rendered once and cached: some 9 min from nothing), its choice's "
      "error. Writes OUT/governor.json and .csv.");
  add_list_option(*governor, "--budget", gv->options.budgets,
                  "Error budgets, percent (default 2, 5, 10)");
  governor->add_option("--error-model", gv->error_model,
                       "The governor's table (default data/lab/error_model.json)");
  governor->add_option("--frames-per-model", gv->options.frames_per_model,
                       "Frames a model change's cost is spread over (0: the frame's cost alone)")
      ->capture_default_str();
  governor->add_option("--out", gv->out, "Output folder")->capture_default_str();
  governor->add_flag("--canonical-only", gv->canonical_only, "No held-out views");
  governor->add_flag("--cached-held-out", gv->cached_held_out,
                     "Only the held-out views whose ground truth is cached: none rendered");
  governor->add_flag("--redo", gv->options.redo, "Check views already checked again");
  governor->add_flag("--quiet", gv->quiet, "No progress lines");
  governor->callback([gv] { run_governor_command(*gv); });

  add_lab_measured_command(*lab);
  add_lab_clarity_command(*lab);
}

}  // namespace planet::apps
