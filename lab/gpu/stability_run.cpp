#include "lab/stability.h"

#include "atmosphere/gpu/registry.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/job.h"
#include "core/tone_map.h"
#include "lab/accuracy.h"
#include "lab/gpu/scene_render.h"
#include "lab/reference_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>

namespace planet {

std::vector<std::pair<std::string, std::string>> stability_points(
    const std::vector<std::string>& techniques) {
  std::vector<std::pair<std::string, std::string>> points;
  for (const std::string& t : techniques.empty() ? technique_names() : techniques) {
    if (auto colon = t.find(':'); colon != std::string::npos) {
      // A choice of one's own, "bruneton:orders=20": that point alone.
      parse_technique(t);  // InputError for a name or setting it does not know
      points.emplace_back(t.substr(0, colon), t.substr(colon + 1));
      continue;
    }
    const TechniqueEntry& entry = technique_entry(t);  // InputError naming the known ones
    std::string cheapest = "default";
    for (const auto& [name, settings] : entry.quality_points) {
      if (name == "cheap") cheapest = name;
    }
    if (cheapest == "default" && !entry.quality_points.empty()) {
      cheapest = entry.quality_points.front().first;
    }
    points.emplace_back(t, "default");
    if (cheapest != "default") points.emplace_back(t, cheapest);
  }
  return points;
}

namespace {

std::optional<StabilityResult> read_result(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return std::nullopt;
  return read_stability_result(file);
}

StabilityResult run_point(const StabilityCell& cell, const std::string& technique,
                          const std::string& quality, const std::optional<ReferenceRender>& truth,
                          const StabilityOptions& o) {
  // A quality point's name or settings of one's own: parse_technique reads both.
  std::string choice = quality == "default" ? technique : technique + ":" + quality;
  StabilityResult r;
  auto start = std::chrono::steady_clock::now();
  try {
    ImageRGB image = render_scene_with(cell.scene, choice);
    r = classify(cell.scene, image, truth ? &truth->image : nullptr,
                 truth ? &truth->noise : nullptr, o.budget_percent);
    ImageRGB shown = image;
    for (float& v : shown.pixels) v = std::isfinite(v) ? v : 0.0f;  // NaN drawn black
    write_tone_mapped_png(stability_result_file(o, cell.scene.name, technique, quality)
                              .replace_extension(".png"),
                          enlarged(shown), cell.scene.exposure);
  } catch (const std::exception& e) {
    r.cls = StabilityClass::kFailed;
    r.reason = e.what();
  }
  r.render_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (r.cls != StabilityClass::kFailed && r.render_s > o.time_limit_s) {
    r.cls = StabilityClass::kFailed;
    r.reason = fmt::format("took {:.3g} s, over the {:g} s limit", r.render_s, o.time_limit_s);
  }
  r.cell = cell.scene.name;
  r.body = cell.body;
  r.technique = technique;
  r.quality = quality;
  r.choice = choice;
  r.point = cell.point;
  r.slices = cell.slices;
  return r;
}

}  // namespace

Job stability_job(const StabilityOptions& o, const std::vector<StabilityCell>& cells) {
  const auto points = stability_points(o.techniques);
  std::vector<JobCell> plan;
  for (const StabilityCell& cell : cells) {
    for (const auto& [technique, quality] : points) {
      plan.push_back({fmt::format("cells/{}/{}-{}.json", cell.scene.name, technique, quality),
                      fmt::format("{} {}:{}", cell.scene.name, technique, quality), cell.scene.name,
                      plan.size()});
    }
  }
  JobOptions options;
  options.redo = o.redo;
  return Job(o.out, plan, options);
}

std::vector<StabilityResult> run_stability(
    const StabilityOptions& o, const std::vector<StabilityCell>& cells,
    const std::function<void(int, int, const std::string&)>& progress) {
  const auto points = stability_points(o.techniques);
  const Job job = stability_job(o, cells);
  auto cell_of = [&](const JobCell& c) -> const StabilityCell& {
    return cells[c.index / points.size()];
  };
  std::optional<ReferenceRender> truth;
  JobSteps steps;
  steps.progress = progress;
  steps.prepare = [&](const JobCell& c) {
    const StabilityCell& cell = cell_of(c);
    std::filesystem::path dir = o.out / "cells" / cell.scene.name;
    std::filesystem::create_directories(dir);
    // Inside the planet there is none: the tracer's medium ends at the ground.
    truth.reset();
    if (cell.point.altitude_m >= 0) {
      truth = reference_render(cell.scene, stability_reference_budget(cell));
      write_tone_mapped_png(dir / "reference.png", enlarged(truth->image), cell.scene.exposure);
    }
  };
  steps.run = [&](const JobCell& c) {
    const auto& [technique, quality] = points[c.index % points.size()];
    return result_to_json(run_point(cell_of(c), technique, quality, truth, o)).dump(2) + "\n";
  };
  job.run(steps);

  // Every shard's results that are there, in the plan's order.
  std::vector<StabilityResult> results;
  std::set<std::string> seen;
  std::error_code ec;
  std::vector<std::filesystem::path> files;
  for (auto it = std::filesystem::recursive_directory_iterator(o.out / "cells", ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->path().extension() == ".json") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    if (auto r = read_result(f)) results.push_back(*r);
  }
  write_stability_tables(o, results);
  return results;
}

}  // namespace planet
