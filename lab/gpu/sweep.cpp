#include "lab/gpu/sweep.h"

#include "atmosphere/gpu/registry.h"
#include "core/atomic_file.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/job.h"
#include "core/tone_map.h"
#include "core/version.h"
#include "gl/texture.h"
#include "governor/governor.h"
#include "lab/accuracy.h"
#include "lab/color_difference.h"
#include "lab/debiased_error.h"
#include "lab/error_png.h"
#include "lab/gpu/error_model_build.h"
#include "lab/gpu/scene_render.h"
#include "lab/pareto.h"
#include "lab/reference_cache.h"
#include "render/frame.h"

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

namespace planet {

namespace {

std::string cell_name(const std::string& technique, const std::string& quality) {
  return technique + "-" + quality;
}

// The choice a quality point makes: "name" or "name:key=value,...".
std::string choice_of(const std::string& technique, const std::string& quality) {
  for (const auto& [name, settings] : technique_entry(technique).quality_points) {
    if (name == quality) return settings.empty() ? technique : technique + ":" + settings;
  }
  return technique;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The scene's camera at another image size (the same vertical field of view).
Scene at_size(Scene scene, int width, int height) {
  scene.width = width;
  scene.height = height;
  return scene;
}

// The commit of the source tree the program runs from, when it is a git
// checkout.
std::string source_commit() {
  std::string command =
      fmt::format("git -C '{}' describe --always --dirty 2>/dev/null", project_root().string());
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[128];
    while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
    pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() ? "not a git checkout" : out;
}

// Times the cell's frames at the display size: the atmosphere's passes,
// synchronous, summed per frame.
void time_cell(const Scene& scene, const std::string& choice, int frames, SweepCell& cell) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  FrameRenderer renderer(scene.width, scene.height);
  FrameOptions options;
  options.synchronous_timing = true;
  renderer.set_options(options);
  renderer.set_body(body, model, make_technique(choice));
  renderer.render(scene.camera, scene.sun_dir_body, scene.exposure);  // warm-up
  std::vector<double> walls, gpus;
  std::map<std::string, std::vector<double>> passes;
  for (int i = 0; i < frames; ++i) {
    double wall = 0, gpu = 0;
    for (const PassTiming& p : renderer.render(scene.camera, scene.sun_dir_body, scene.exposure).passes) {
      if (p.skipped || p.pass == "surface" || p.pass == "tonemap") continue;
      wall += p.wall_ms;
      gpu += p.gpu_ms;
      passes[p.pass].push_back(p.wall_ms);
    }
    walls.push_back(wall);
    gpus.push_back(gpu);
  }
  cell.wall_ms = median(walls);
  cell.wall_spread_ms = walls.empty() ? 0.0
                                      : *std::max_element(walls.begin(), walls.end()) -
                                            *std::min_element(walls.begin(), walls.end());
  cell.gpu_ms = median(gpus);
  for (auto& [pass, ms] : passes) cell.pass_wall_ms[pass] = median(ms);
}

struct SceneTruth {
  ImageRGB image, noise;
  ImageRGB first_order, first_order_noise;  // the first order alone, its noise
  ImageRGB higher_orders, higher_orders_noise;  // image - first_order, its noise
  std::vector<uint8_t> sun_mask;
  std::vector<uint8_t> reference_rgb8;
};

// a - b, pixel by pixel.
ImageRGB difference(const ImageRGB& a, const ImageRGB& b) {
  ImageRGB out = a;
  for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] -= b.pixels[i];
  return out;
}

// The standard error of the difference of two independent renders.
ImageRGB combined_noise(const ImageRGB& a, const ImageRGB& b) {
  ImageRGB out = a;
  for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = std::hypot(a.pixels[i], b.pixels[i]);
  return out;
}

void measure_cell(const Scene& scene, const std::string& choice, const SceneTruth& truth,
                  const std::filesystem::path& image_stem, SweepCell& cell) {
  ImageRGB image = render_scene_with(scene, choice);
  TechniqueAccuracy accuracy = measure_accuracy(scene, image, truth.image);
  std::array<DebiasedError, 3> e = debiased_error(image, truth.image, truth.noise, truth.sun_mask);
  for (size_t c = 0; c < 3; ++c) {
    cell.relative_rmse[c] = accuracy.channels[c].relative();
    cell.debiased[c] = e[c].relative(e[c].debiased_rmse);
    cell.debiased_low[c] = e[c].relative(e[c].low);
    cell.debiased_high[c] = e[c].relative(e[c].high);
  }
  // The split by order: the technique's first order against the truth's,
  // and the rest of each against the other's.
  ImageRGB first = render_first_order_with(scene, choice);
  std::array<DebiasedError, 3> single =
      debiased_error(first, truth.first_order, truth.first_order_noise, truth.sun_mask);
  std::array<DebiasedError, 3> higher =
      debiased_error(difference(image, first), truth.higher_orders, truth.higher_orders_noise,
                     truth.sun_mask);
  for (size_t c = 0; c < 3; ++c) {
    double mean = e[c].mean_reference;
    cell.single_error[c] = mean > 0 ? single[c].debiased_rmse / mean : 0.0;
    cell.higher_error[c] = mean > 0 ? higher[c].debiased_rmse / mean : 0.0;
  }
  cell.split = true;
  cell.worst_pixel = 0;
  for (size_t i = 0; i < truth.sun_mask.size(); ++i) {
    if (truth.sun_mask[i]) continue;
    for (size_t c = 0; c < 3; ++c) {
      cell.worst_pixel =
          std::max(cell.worst_pixel, double(std::abs(accuracy.signed_error.pixels[i * 3 + c])));
    }
  }
  cell.ciede2000 = mean_ciede2000(tone_mapped_rgb8(image, scene.exposure), truth.reference_rgb8,
                                  truth.sun_mask);
  // The images a person looks at: the technique's and its error.
  write_tone_mapped_png(image_stem.string() + "_technique.png", enlarged(image), scene.exposure);
  ImageRGB error = accuracy.signed_error;
  for (float& v : error.pixels) v = std::abs(v);
  write_error_png(image_stem.string() + "_error.png", error);
}

// The geometric mean of positive values (0 where any is not).
double geometric_mean(const std::vector<double>& v) {
  double log_sum = 0;
  for (double x : v) {
    if (!(x > 0)) return 0.0;
    log_sum += std::log(x);
  }
  return v.empty() ? 0.0 : std::exp(log_sum / double(v.size()));
}

}  // namespace

uintmax_t sweep_disk_table_bytes(const SweepPlan& plan) {
  std::set<std::string> models;
  for (const Scene& scene : plan.scenes) {
    models.insert(
        reference_model_key(scene_atmosphere(scene, scene_body(scene)), ReferenceMode::kRgb));
  }
  uintmax_t per_model = 0;
  for (const auto& [technique, quality] : plan.points) {
    std::string choice = choice_of(technique, quality);
    per_model += disk_table_bytes(parse_technique(choice)) +
                 disk_table_bytes(parse_technique(single_scattering_text(choice)));
  }
  return per_model * models.size();
}

PathBudget sweep_reference_budget(const SweepOptions& o, const Scene& scene) {
  if (o.paths) return *o.paths;
  std::optional<PathBudget> cached = best_cached_budget(scene, ReferenceMode::kRgb);
  return cached ? *cached : lab_reference_paths(scene);
}

Scene first_order_scene(Scene scene) {
  scene.max_order = 1;
  return scene;
}

double SweepCell::error() const {
  return std::max({debiased[0], debiased[1], debiased[2]});
}

namespace {
size_t worst_channel(const SweepCell& c) {
  return size_t(std::max_element(c.debiased.begin(), c.debiased.end()) - c.debiased.begin());
}

// The point as the fronts weigh it: its time with its frames' spread, its
// error with its interval.
CostError cost_error(const SweepCell& c) {
  return {c.wall_ms, c.error(), c.wall_spread_ms, c.error_low(), c.error_high()};
}
}  // namespace

double SweepCell::error_low() const { return debiased_low[worst_channel(*this)]; }
double SweepCell::error_high() const { return debiased_high[worst_channel(*this)]; }

SweepPlan plan_sweep(const SweepOptions& o) {
  if (o.frames < 1 || o.frames > 1000) {
    throw InputError(fmt::format("lab run --frames: {} is not 1 to 1000", o.frames));
  }
  SweepPlan plan;
  std::vector<std::string> techniques = o.techniques.empty() ? technique_names() : o.techniques;
  std::set<std::string> qualities_used;
  for (const std::string& t : techniques) {
    const TechniqueEntry& entry = technique_entry(t);  // InputError naming the known ones
    std::vector<std::string> names;
    for (const auto& point : entry.quality_points) names.push_back(point.first);
    if (names.empty()) names.push_back("default");
    for (const std::string& q : names) {
      bool wanted = o.qualities.empty() ||
                    std::find(o.qualities.begin(), o.qualities.end(), q) != o.qualities.end();
      if (!wanted) continue;
      plan.points.emplace_back(t, q);
      qualities_used.insert(q);
    }
  }
  for (const std::string& q : o.qualities) {
    if (!qualities_used.count(q)) {
      throw InputError(fmt::format(
          "lab run --quality: no technique of the sweep has a quality point '{}' (planet "
          "techniques lists them)",
          q));
    }
  }
  if (o.scenes.empty()) {
    for (const Scene& s : canonical_scenes()) {
      if (scene_body(s).has_atmosphere()) plan.scenes.push_back(at_size(s, o.width, o.height));
    }
  } else {
    for (const std::string& name : o.scenes) {
      Scene s = at_size(find_scene(name), o.width, o.height);
      scene_atmosphere(s, scene_body(s));  // an airless scene fails here
      plan.scenes.push_back(s);
    }
  }
  return plan;
}

nlohmann::json cell_to_json(const SweepCell& c) {
  return {{"scene", c.scene},
          {"technique", c.technique},
          {"quality", c.quality},
          {"choice", c.choice},
          {"wall_ms", c.wall_ms},
          {"wall_spread_ms", c.wall_spread_ms},
          {"gpu_ms", c.gpu_ms},
          {"pass_wall_ms", c.pass_wall_ms},
          {"relative_rmse", c.relative_rmse},
          {"debiased_relative_rmse", c.debiased},
          {"debiased_low", c.debiased_low},
          {"debiased_high", c.debiased_high},
          {"worst_pixel", c.worst_pixel},
          {"ciede2000", c.ciede2000},
          {"single_error", c.split ? nlohmann::json(c.single_error) : nlohmann::json()},
          {"higher_error", c.split ? nlohmann::json(c.higher_error) : nlohmann::json()},
          {"error", c.error()},
          {"on_front", c.on_front},
          {"time_ties", c.time_ties}};
}

SweepCell cell_from_json(const nlohmann::json& json, const std::string& file) {
  return read_job_json(json, file, "planet lab run", [](const nlohmann::json& j) {
    SweepCell c;
    c.scene = j.at("scene").get<std::string>();
    c.technique = j.at("technique").get<std::string>();
    c.quality = j.at("quality").get<std::string>();
    c.choice = j.at("choice").get<std::string>();
    c.wall_ms = j.at("wall_ms").get<double>();
    c.wall_spread_ms = j.at("wall_spread_ms").get<double>();
    c.gpu_ms = j.at("gpu_ms").get<double>();
    c.pass_wall_ms = j.at("pass_wall_ms").get<std::map<std::string, double>>();
    c.relative_rmse = j.at("relative_rmse").get<std::array<double, 3>>();
    c.debiased = j.at("debiased_relative_rmse").get<std::array<double, 3>>();
    c.debiased_low = j.at("debiased_low").get<std::array<double, 3>>();
    c.debiased_high = j.at("debiased_high").get<std::array<double, 3>>();
    c.worst_pixel = j.at("worst_pixel").get<double>();
    c.ciede2000 = j.at("ciede2000").get<double>();
    // Cells of an earlier sweep may lack the split: null, or not there.
    if (j.contains("single_error") && !j.at("single_error").is_null()) {
      c.single_error = j.at("single_error").get<std::array<double, 3>>();
      c.higher_error = j.at("higher_error").get<std::array<double, 3>>();
      c.split = true;
    }
    return c;
  });
}

SweepCell read_sweep_cell(const std::filesystem::path& file) {
  return cell_from_json(read_job_file(file, "planet lab run"), file.string());
}

std::vector<ProgressPart> sweep_cell_costs(const SweepOptions& o, const SweepPlan& plan) {
  // The shipped table's times per choice, ms: the mean frame over its
  // scenes at its time size, and the model change. Without the table every
  // cell weighs the same until cells of its kind are timed.
  std::map<std::string, std::pair<double, int>> frames;
  std::map<std::string, double> changes;
  double pixels_ratio = 1;
  try {
    ErrorModel table = load_error_model(shipped_error_model_file());
    for (const ViewClass& view : table.classes) {
      for (const ErrorModelEntry& entry : view.entries) {
        frames[entry.choice].first += entry.frame_ms;
        frames[entry.choice].second += 1;
      }
    }
    changes = table.model_change_ms;
    if (table.time_width > 0 && table.time_height > 0) {
      pixels_ratio =
          double(o.time_width) * o.time_height / (double(table.time_width) * table.time_height);
    }
  } catch (const std::exception&) {
    frames.clear();
    changes.clear();
  }
  // A cell's own work beside its frames and tables: two renderers made,
  // two renders at the accuracy size measured, its images written; about
  // a second here (hillaire's cells took 2 s in all, their frames and
  // tables taking the rest at the table's times, slowed by other work).
  constexpr double kCellFixedMs = 1000;
  std::vector<ProgressPart> parts;
  for (size_t s = 0; s < plan.scenes.size(); ++s) {
    for (const auto& [technique, quality] : plan.points) {
      std::string choice = governor_choice(technique, quality);
      double prior = 1;
      if (!frames.empty()) {
        auto frame = frames.find(choice);
        auto change = changes.find(choice);
        double frame_ms = frame != frames.end() ? frame->second.first / frame->second.second : 0;
        double change_ms = change != changes.end() ? change->second : 0;
        // The frames timed and the one before them; the tables of the timed
        // technique and of its single scattering.
        prior = kCellFixedMs + (o.frames + 1) * frame_ms * pixels_ratio + 2 * change_ms;
      }
      parts.push_back({choice, prior});
    }
  }
  return sweep_job(o, plan).parts(parts);
}

Job sweep_job(const SweepOptions& o, const SweepPlan& plan) {
  std::vector<JobCell> cells;
  for (const Scene& scene : plan.scenes) {
    for (const auto& [technique, quality] : plan.points) {
      cells.push_back({fmt::format("cells/{}/{}.json", scene.name, cell_name(technique, quality)),
                       fmt::format("{} {}:{}", scene.name, technique, quality), scene.name,
                       cells.size()});
    }
  }
  JobOptions options;
  options.redo = o.redo;
  return Job(o.out, cells, options);
}

namespace {

// Runs the cells not yet done and reads the others back, in the plan's order.
std::vector<SweepCell> sweep_cells(
    const SweepOptions& o, const SweepPlan& plan,
    const std::function<void(int, int, const std::string&)>& progress) {
  const Job job = sweep_job(o, plan);
  std::vector<SweepCell> cells;
  SceneTruth truth;
  auto scene_of = [&](size_t index) -> const Scene& {
    return plan.scenes[index / plan.points.size()];
  };
  JobSteps steps;
  steps.progress = progress;
  steps.prepare = [&](const JobCell& cell) {
    // The ground truth once per scene: the best cached or shipped, else
    // rendered (the command has said what that costs).
    const Scene& scene = scene_of(cell.index);
    ReferenceRender reference =
        reference_render(scene, sweep_reference_budget(o, scene), ReferenceMode::kRgb);
    Scene first = first_order_scene(scene);
    ReferenceRender first_order =
        reference_render(first, sweep_reference_budget(o, first), ReferenceMode::kRgb);
    truth = {reference.image,
             reference.noise,
             first_order.image,
             first_order.noise,
             difference(reference.image, first_order.image),
             combined_noise(reference.noise, first_order.noise),
             sun_disk_mask(scene),
             tone_mapped_rgb8(reference.image, scene.exposure)};
    std::filesystem::path dir = o.out / "cells" / scene.name;
    std::filesystem::create_directories(dir);
    write_tone_mapped_png(dir / "reference.png", enlarged(truth.image), scene.exposure);
  };
  steps.keep = [&](const JobCell&, const std::filesystem::path& file) {
    cells.push_back(read_sweep_cell(file));
    cells.back().kept = true;
    return true;
  };
  steps.run = [&](const JobCell& job_cell) {
    size_t index = job_cell.index;
    const Scene& scene = scene_of(index);
    const auto& [technique, quality] = plan.points[index % plan.points.size()];
    SweepCell cell;
    cell.scene = scene.name;
    cell.technique = technique;
    cell.quality = quality;
    cell.choice = choice_of(technique, quality);
    time_cell(at_size(scene, o.time_width, o.time_height), cell.choice, o.frames, cell);
    measure_cell(scene, cell.choice, truth,
                 o.out / "cells" / scene.name / cell_name(technique, quality), cell);
    cells.push_back(cell);
    return cell_to_json(cell).dump(2) + "\n";
  };
  job.run(steps);
  return cells;
}

std::string point_name(const std::string& technique, const std::string& quality) {
  return technique + ":" + quality;
}

// The fronts per scene; points within each other's noise tie (pareto.h).
void mark_scene_fronts(std::vector<SweepCell>& cells) {
  std::map<std::string, std::vector<size_t>> by_scene;
  for (size_t i = 0; i < cells.size(); ++i) by_scene[cells[i].scene].push_back(i);
  for (auto& [scene, indices] : by_scene) {
    std::vector<CostError> points;
    for (size_t i : indices) points.push_back(cost_error(cells[i]));
    std::vector<bool> on = pareto_front(points);
    std::vector<std::vector<size_t>> ties = cost_ties(points);
    for (size_t k = 0; k < indices.size(); ++k) {
      SweepCell& cell = cells[indices[k]];
      cell.on_front = on[k];
      cell.time_ties.clear();
      for (size_t t : ties[k]) {
        cell.time_ties.push_back(
            point_name(cells[indices[t]].technique, cells[indices[t]].quality));
      }
    }
  }
}

// The front over the scenes' geometric means, a point each.
nlohmann::json overall_front(const SweepPlan& plan, const std::vector<SweepCell>& cells) {
  nlohmann::json overall = nlohmann::json::array();
  std::vector<CostError> overall_points;
  for (const auto& [technique, quality] : plan.points) {
    std::vector<double> times, errors, lows, highs;
    double relative_spread = 0;
    for (const SweepCell& c : cells) {
      if (c.technique == technique && c.quality == quality) {
        times.push_back(c.wall_ms);
        errors.push_back(c.error());
        lows.push_back(c.error_low());
        highs.push_back(c.error_high());
        relative_spread += c.wall_ms > 0 ? c.wall_spread_ms / c.wall_ms : 0.0;
      }
    }
    // The spread of the mean time: the cells' mean spread relative to
    // their times, at the mean time.
    double time = geometric_mean(times);
    double spread = times.empty() ? 0.0 : time * relative_spread / double(times.size());
    overall_points.push_back(
        {time, geometric_mean(errors), spread, geometric_mean(lows), geometric_mean(highs)});
    overall.push_back({{"technique", technique},
                       {"quality", quality},
                       {"choice", choice_of(technique, quality)},
                       {"wall_ms", overall_points.back().cost},
                       {"wall_spread_ms", spread},
                       {"error", overall_points.back().error}});
  }
  std::vector<bool> overall_on = pareto_front(overall_points);
  std::vector<std::vector<size_t>> overall_ties = cost_ties(overall_points);
  for (size_t i = 0; i < overall.size(); ++i) {
    overall[i]["on_front"] = bool(overall_on[i]);
    std::vector<std::string> ties;
    for (size_t t : overall_ties[i]) {
      ties.push_back(point_name(plan.points[t].first, plan.points[t].second));
    }
    overall[i]["time_ties"] = ties;
  }
  return overall;
}

std::string sweep_csv(const std::vector<SweepCell>& cells) {
  std::string csv =
      "scene,technique,quality,choice,wall_ms,wall_spread_ms,gpu_ms,rel_rmse_r,rel_rmse_g,"
      "rel_rmse_b,debiased_r,debiased_g,debiased_b,debiased_low_r,debiased_low_g,debiased_low_b,"
      "debiased_high_r,debiased_high_g,debiased_high_b,worst_pixel,ciede2000,error,on_front,"
      "single_r,single_g,single_b,higher_r,higher_g,higher_b,time_ties\n";
  for (const SweepCell& c : cells) {
    csv += fmt::format("{},{},{},\"{}\",{:.4f},{:.4f},{:.4f}", c.scene, c.technique, c.quality,
                       c.choice, c.wall_ms, c.wall_spread_ms, c.gpu_ms);
    for (const auto* v : {&c.relative_rmse, &c.debiased, &c.debiased_low, &c.debiased_high}) {
      for (double x : *v) csv += fmt::format(",{:.6f}", x);
    }
    csv += fmt::format(",{:.6f},{:.4f},{:.6f},{}", c.worst_pixel, c.ciede2000, c.error(),
                       c.on_front ? 1 : 0);
    for (const auto* v : {&c.single_error, &c.higher_error}) {
      for (double x : *v) csv += c.split ? fmt::format(",{:.6f}", x) : std::string(",");
    }
    csv += fmt::format(",\"{}\"\n", fmt::join(c.time_ties, ";"));
  }
  return csv;
}

}  // namespace

std::vector<SweepCell> run_sweep(
    const SweepOptions& o, const SweepPlan& plan,
    const std::function<void(int, int, const std::string&)>& progress) {
  std::vector<SweepCell> cells = sweep_cells(o, plan, progress);
  mark_scene_fronts(cells);
  nlohmann::json overall = overall_front(plan, cells);
  nlohmann::json results = {
      {"planet", planet_version()},
      {"commit", source_commit()},
      {"renderer", reinterpret_cast<const char*>(glGetString(GL_RENDERER))},
      {"time_size", {o.time_width, o.time_height}},
      {"accuracy_size", {o.width, o.height}},
      {"frames", o.frames},
      {"cost", "wall_ms: the atmosphere's passes per frame, synchronous, median of the frames"},
      {"ties",
       "time_ties: the points whose wall_ms ties with its own: their wall_spread_ms (max - min "
       "of the frames), each centred on its wall_ms, overlap; on the fronts a point is off only "
       "where another is as cheap and as accurate within the spreads and the errors' 95 % "
       "intervals, and better beyond them on one"},
      {"error", "the worst channel's relative RMSE against the ground truth, its noise taken out"},
      {"split",
       "single_error: the technique's first order against the ground truth's; higher_error: the "
       "orders above the first, each's against the other's; debiased relative RMSE per channel"},
      {"cells", nlohmann::json::array()},
      {"overall", overall}};
  for (const SweepCell& c : cells) results["cells"].push_back(cell_to_json(c));
  write_file_atomically(o.out / "results.json", results.dump(2) + "\n");

  write_file_atomically(o.out / "results.csv", sweep_csv(cells));
  return cells;
}

}  // namespace planet
