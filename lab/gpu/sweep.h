#pragma once
// The lab's sweep: every (technique, quality point, canonical scene) cell
// timed on the scene's view at a display size and measured against the
// scene's ground truth at the reference's size, with the reference's noise
// taken out (debiased_error.h), and split into the first order of
// scattering and the orders above it. Cells are kept one file each as they
// finish, so that a sweep stopped part-way goes on where it stopped; the
// fronts and tables are made from whatever cells are there.
#include <nlohmann/json.hpp>
#include "core/job.h"
#include "core/progress.h"
#include "lab/scene.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct SweepOptions {
  std::vector<std::string> techniques;  // registry names; empty: every one
  std::vector<std::string> qualities;   // quality point names; empty: every one
  std::vector<std::string> scenes;      // canonical scenes; empty: those with air
  std::filesystem::path out = "out/lab";
  int frames = 5;                       // timed after one untimed frame
  int time_width = 640, time_height = 360;
  int width = kLabWidth, height = kLabHeight;  // accuracy: the lab's shipped references' size
  std::optional<PathBudget> paths;      // references not cached: this budget
  bool redo = false;                    // time and measure finished cells again
};

struct SweepCell {
  std::string scene, technique, quality, choice;  // choice: "name:key=value,..."
  double wall_ms = 0, wall_spread_ms = 0;  // median and max - min of the frames' sums
  double gpu_ms = 0;                       // timer queries' median sum
  std::map<std::string, double> pass_wall_ms;
  std::array<double, 3> relative_rmse{};   // plain, reference noise included
  std::array<double, 3> debiased{};        // the reference's noise taken out
  std::array<double, 3> debiased_low{}, debiased_high{};  // 95 % intervals
  double worst_pixel = 0;                  // largest |t - r| / mean reference, any channel
  double ciede2000 = 0;                    // mean, tone-mapped images
  // The error split by order, each the debiased RMSE over the full
  // reference's mean: the technique confined to single scattering
  // (render_first_order_with) against the ground truth's first order, and
  // what the orders above the first add, the technique's against the
  // ground truth's (full minus first order in each).
  std::array<double, 3> single_error{}, higher_error{};
  bool split = false;                      // the two above were measured
  double error() const;                    // the worst channel's debiased relative RMSE
  double error_low() const, error_high() const;  // that channel's 95 % interval
  bool on_front = false;                   // of its scene
  // The scene's other points ("technique:quality") whose time ties with
  // its own (their frames' spreads, centred on the times, overlap): which
  // is the faster, the frames do not tell.
  std::vector<std::string> time_ties;
  bool kept = false;                       // read from an earlier run, not timed now
};

// The sweep's cells, in order: scenes, then techniques, then quality points.
struct SweepPlan {
  std::vector<Scene> scenes;  // at the accuracy size
  std::vector<std::pair<std::string, std::string>> points;  // technique, quality
};

// Checks every name and the output folder (InputError) before any work.
SweepPlan plan_sweep(const SweepOptions& options);

// The sweep as a job (core/job.h): a cell per (scene, point) in the plan's
// order, each kept in OUT/cells/<scene>/<technique>-<quality>.json, the
// scene's cells a group that shares its ground truth.
Job sweep_job(const SweepOptions& options, const SweepPlan& plan);

// The bytes of disk-cached tables the sweep makes and reads again (each
// point's and its first order's, per distinct model of its scenes): what
// the bruneton cache must keep for no cell to wait on a table pushed out.
uintmax_t sweep_disk_table_bytes(const SweepPlan& plan);

// The budget of the scene's ground truth in the sweep: options.paths if
// given, else the best cached or shipped, else the lab's paths
// (lab_reference_paths).
PathBudget sweep_reference_budget(const SweepOptions& options, const Scene& scene);
// The scene's ground truth's first order (single scattering), which the
// sweep splits each cell's error by.
Scene first_order_scene(Scene scene);

// What the progress line's time left weighs each cell by, in the plan's
// order: its kind (technique:quality, whose finished cells tell the time of
// the others), and a prior cost from the shipped governor's table (the
// choice's frame time over the timed frames, its model change for the
// tables the cell builds, and a fixed part); 0 for a cell kept from an
// earlier run.
std::vector<ProgressPart> sweep_cell_costs(const SweepOptions& options, const SweepPlan& plan);

// Runs the cells not yet done (all with redo), then writes results.json,
// results.csv and the cells' images under options.out. Needs a GL context.
// `progress` sees (cells done, cells in all, the cell now).
std::vector<SweepCell> run_sweep(const SweepOptions& options, const SweepPlan& plan,
                                 const std::function<void(int, int, const std::string&)>& progress);

nlohmann::json cell_to_json(const SweepCell& cell);
// InputError naming `file` for a cell file this program did not write.
SweepCell cell_from_json(const nlohmann::json& json, const std::string& file);
// A cell a sweep wrote (cells/<scene>/<technique>-<quality>.json); InputError
// naming the file for anything else.
SweepCell read_sweep_cell(const std::filesystem::path& file);

}  // namespace planet
