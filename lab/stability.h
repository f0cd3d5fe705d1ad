#pragma once
// The stability map: where each technique holds and where it breaks. Each
// body preset (Earth, Mars, the asteroid) is varied along one axis at a
// time, and over two planes (density x Mie g, bottom radius x camera
// altitude); every cell is a small view with its own path-traced ground
// truth, and every (technique, quality) drawn there is classified: ok,
// inaccurate, NaN or Inf, exploded, or failed, with the reason kept.
// Cells are kept one file each as they finish, and split into shards by
// cell, so that a sweep goes on where it stopped and can run across
// machines.
#include "core/image_io.h"
#include "core/job.h"
#include "lab/scene.h"

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace planet {

// What a cell changes about its body preset; the defaults are the preset.
struct StabilityPoint {
  double density = 1.0;                // scattering and absorption multiplied
  std::optional<double> mie_g;         // none: the preset's
  std::optional<double> bottom_radius; // metres; none: the preset's
  bool absolute_thickness = false;     // with bottom_radius: see with_bottom_radius
  double scale_height = 1.0;           // scale heights multiplied, optical depth kept
  double altitude_m = 2.0;             // the camera's, above the ground; < 0: inside the planet
  double sun_elevation_deg = 60.0;

  // "d50-g0.95": the values that differ from the preset, for names.
  std::string label() const;
  nlohmann::json to_json() const;
};

struct StabilityCell {
  std::string body;                 // earth, mars, asteroid
  StabilityPoint point;
  std::vector<std::string> slices;  // "density", "g", ..., "density_g", "radius_altitude"
  Scene scene;                      // at the map's size
};

// The axes, one name each as slices and the report use them.
struct StabilityAxis {
  std::string name;    // density, g, radius, radius_absolute, scale_height, altitude, sun
  std::string label;   // with its unit
  std::vector<double> values;
};
std::vector<StabilityAxis> stability_axes(const std::string& body);
// The bodies the map varies: earth, mars, asteroid.
const std::vector<std::string>& stability_bodies();

// The view of a cell: from the ground up, the preset's sky (pitched 35
// degrees up, a 90 degree field, the sun 30 degrees to the right); from
// higher, pitched down as the horizon dips; from far enough that the shell
// fills less than 90 degrees, the whole disc, centred.
Scene stability_scene(const std::string& body, const StabilityPoint& point, int width, int height);

constexpr int kStabilityWidth = 16, kStabilityHeight = 8;

enum class StabilityClass { kOk, kInaccurate, kNaN, kExploded, kFailed };
std::string to_string(StabilityClass c);

struct StabilityOptions {
  std::vector<std::string> techniques;  // empty: every one
  std::vector<std::string> bodies;      // empty: stability_bodies()
  std::filesystem::path out = "out/lab/stability";
  double budget_percent = 5.0;          // ok within it
  double time_limit_s = 120.0;          // a cell's render over it: failed
  int width = kStabilityWidth, height = kStabilityHeight;
  std::vector<std::string> cells;       // by name; empty: every one
  int shard = 1, shards = 1;            // this machine's cells: index % shards == shard - 1
  bool redo = false;
};

struct StabilityResult {
  std::string cell, body, technique, quality, choice;
  StabilityPoint point;
  std::vector<std::string> slices;
  StabilityClass cls = StabilityClass::kOk;
  std::string reason;                    // what failed, or where it blew up
  std::array<double, 3> error{}, low{}, high{};  // debiased relative RMSE per channel, 95 %
  double worst() const;                  // the worst channel's error
  double worst_ratio = 0;                // the largest pixel over its reference's value
  double render_s = 0;                   // the technique's tables and frame
  double reference_noise = 0;            // the reference's noise over its mean, worst channel
};

// The (technique, quality) points the map draws: each technique at its
// default and at its cheapest quality point (the first the registry lists);
// InputError for a name or setting the registry does not know. In
// planet_lab_gpu with the registry, as run_stability; the rest of this
// header is planet_lab's, on the CPU.
std::vector<std::pair<std::string, std::string>> stability_points(
    const std::vector<std::string>& techniques);

// Where a (cell, technique, quality)'s result is kept: OUT/cells/CELL/T-Q.json.
std::filesystem::path stability_result_file(const StabilityOptions& options,
                                            const std::string& cell, const std::string& technique,
                                            const std::string& quality);

// Every cell of the map (one per distinct view; a cell on several slices
// lists each), in order: bodies, then slices. Checks the bodies, the
// budget, the time limit and the shard first (stability_points checks the
// techniques).
std::vector<StabilityCell> plan_stability(const StabilityOptions& options);
// This shard's cells.
std::vector<StabilityCell> shard_cells(const std::vector<StabilityCell>& cells, int shard,
                                       int shards);
// The cells of these names, in this order (all of them for none);
// InputError for a name that is not one.
std::vector<StabilityCell> named_cells(const std::vector<StabilityCell>& cells,
                                       const std::vector<std::string>& names);
// "2/5" into (2, 5); InputError otherwise.
std::pair<int, int> parse_shard(const std::string& text);

// The ground truth's budget for a cell: 1024 paths per pixel, fewer where
// the air is dense (paths there scatter hundreds of times; their noise is
// taken out of the errors).
PathBudget stability_reference_budget(const StabilityCell& cell);
// What rendering that ground truth takes on this project's 2-core machine,
// in seconds (from a full default sweep: docs/stability.md#the-whole-sweep).
double stability_reference_seconds(const StabilityCell& cell);

// Classifies a technique's image of a cell against the cell's ground truth
// and its noise; with none (a camera inside the planet), by its values
// alone: not finite, or below zero. Errors are relative to the reference's
// mean, or to a hundred-thousandth of the sun's irradiance where the mean
// is below that (a sky with next to nothing in it).
StabilityResult classify(const Scene& scene, const ImageRGB& image, const ImageRGB* reference,
                         const ImageRGB* noise, double budget_percent);

// The map's draws as a job (core/job.h): a (cell, point) each, kept in
// stability_result_file, the cell's draws a group that shares its ground
// truth. In planet_lab_gpu, as stability_points.
Job stability_job(const StabilityOptions& options, const std::vector<StabilityCell>& cells);

// Runs this shard's cells not yet done: renders each cell's ground truth
// (cached), draws every point and classifies it, keeping one file per
// (cell, point); then gathers every result under options.out (every
// shard's) into stability.json and stability.csv. Needs a GL context.
std::vector<StabilityResult> run_stability(
    const StabilityOptions& options, const std::vector<StabilityCell>& cells,
    const std::function<void(int, int, const std::string&)>& progress);

// stability.json and stability.csv under options.out: the results, each
// body's preset and axes, and the counts per class.
void write_stability_tables(const StabilityOptions& options,
                            const std::vector<StabilityResult>& results);

nlohmann::json result_to_json(const StabilityResult& result);
StabilityResult result_from_json(const nlohmann::json& json, const std::string& file);
// A cell the map wrote; InputError naming the file for anything else.
StabilityResult read_stability_result(const std::filesystem::path& file);

}  // namespace planet
