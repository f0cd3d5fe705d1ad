#include "lab/gpu/governor_check.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/job.h"
#include "lab/accuracy.h"
#include "lab/debiased_error.h"
#include "lab/gpu/scene_render.h"
#include "lab/gpu/sweep.h"
#include "lab/reference_cache.h"
#include "lab/stability.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

namespace planet {

namespace {

// The one-axis slices of the stability map: other altitudes, sun
// elevations, densities, asymmetries, scale heights and radii than the
// lab's scenes.
const std::vector<std::string> kHeldOutSlices = {"altitude", "sun",          "density", "g",
                                                 "scale_height", "radius"};

struct View {
  Scene scene;
  bool held_out = false;
  std::optional<StabilityCell> cell;
};

nlohmann::json check_to_json(const GovernorCheck& c) {
  return {{"budget_percent", c.budget_percent},
          {"view", c.view},
          {"held_out", c.held_out},
          {"choice", c.choice},
          {"predicted_error", c.predicted_error},
          {"measured_error", c.measured_error},
          {"measured_high", c.measured_high},
          {"reference_noise", c.reference_noise},
          {"cost_ms", c.cost_ms},
          {"cheapest", c.cheapest},
          {"cheapest_cost_ms", c.cheapest_cost_ms},
          {"within_budget", c.within_budget()}};
}

GovernorCheck check_from_json(const nlohmann::json& j) {
  GovernorCheck c;
  c.budget_percent = j.at("budget_percent").get<double>();
  c.view = j.at("view").get<std::string>();
  c.held_out = j.at("held_out").get<bool>();
  c.choice = j.at("choice").get<std::string>();
  c.predicted_error = j.at("predicted_error").get<double>();
  c.measured_error = j.at("measured_error").get<double>();
  c.measured_high = j.at("measured_high").get<double>();
  c.reference_noise = j.at("reference_noise").get<double>();
  c.cost_ms = j.at("cost_ms").get<double>();
  c.cheapest = j.at("cheapest").get<std::string>();
  c.cheapest_cost_ms = j.at("cheapest_cost_ms").get<double>();
  return c;
}

// The stability map's one-axis cells with a ground truth (not inside the
// planet).
std::vector<StabilityCell> held_out_cells() {
  std::vector<StabilityCell> out;
  for (const StabilityCell& cell : plan_stability(StabilityOptions{})) {
    if (cell.point.altitude_m < 0) continue;  // inside the planet: no ground truth
    bool one_axis = std::any_of(cell.slices.begin(), cell.slices.end(), [](const std::string& s) {
      return std::find(kHeldOutSlices.begin(), kHeldOutSlices.end(), s) != kHeldOutSlices.end();
    });
    if (one_axis) out.push_back(cell);
  }
  return out;
}

bool truth_cached(const StabilityCell& cell) {
  return reference_cached(cell.scene, stability_reference_budget(cell), ReferenceMode::kRgb);
}

ErrorModel load_model(const GovernorCheckOptions& o) {
  return load_error_model(o.error_model.empty() ? shipped_error_model_file() : o.error_model);
}

std::vector<View> views(const GovernorCheckOptions& o, const ErrorModel& model) {
  std::vector<View> out;
  for (const ViewClass& c : model.classes) {
    Scene scene = find_scene(c.scene);
    scene.width = kLabWidth;
    scene.height = kLabHeight;
    out.push_back({scene, false, std::nullopt});
  }
  if (!o.held_out) return out;
  for (const StabilityCell& cell : held_out_cells()) {
    if (!o.render_held_out && !truth_cached(cell)) continue;
    out.push_back({cell.scene, true, cell});
  }
  return out;
}

}  // namespace

void check_governor_options(const GovernorCheckOptions& o) {
  if (o.budgets.empty()) throw InputError("lab governor: --budget: give at least one");
  for (double b : o.budgets) checked_error_budget(b, "lab governor --budget");
  if (!(o.frames_per_model >= 0)) {
    throw InputError("lab governor --frames-per-model: must be 0 (the frame alone) or more");
  }
  load_model(o);
}

HeldOutTruths held_out_truths(const GovernorCheckOptions& o) {
  HeldOutTruths t;
  if (!o.held_out) return t;
  for (const StabilityCell& cell : held_out_cells()) {
    if (truth_cached(cell)) {
      ++t.cached;
    } else if (o.render_held_out) {
      ++t.to_render;
      t.seconds += stability_reference_seconds(cell);
    }
  }
  return t;
}

namespace {

// What a view's checks share: its ground truth, rendered for the first
// choice measured, and each choice drawn once (its error, high end and the
// truth's noise).
struct ViewMeasures {
  std::optional<ReferenceRender> truth;
  std::map<std::string, std::pair<std::array<double, 2>, double>> measured;
};

GovernorCheck check_view(const ErrorModel& model, const GovernorCheckOptions& o, const View& v,
                         double budget, ViewMeasures& m) {
  GovernorSettings settings;
  settings.budget_percent = budget;
  settings.frames_per_model = o.frames_per_model;
  Governor governor(model, settings, "hillaire");
  Body body = scene_body(v.scene);
  AtmosphereModel atmosphere = scene_atmosphere(v.scene, body);
  const ViewFeatures features =
      view_features(body, atmosphere, v.scene.camera.pos_body, v.scene.sun_dir_body);
  // Every choice as the table has it, before any is drawn (the costs
  // then include each one's model change, as the choice's does).
  const std::vector<Prediction> table = governor.predict(features);
  GovernorDecision d = governor.decide(features);
  GovernorCheck c;
  c.budget_percent = budget;
  c.view = v.scene.name;
  c.held_out = v.held_out;
  c.choice = d.choice;
  c.predicted_error = d.chosen.error;
  c.cost_ms = d.chosen.cost_ms;
  if (!m.measured.count(d.choice)) {
    if (!m.truth) {
      PathBudget paths = v.cell ? stability_reference_budget(*v.cell)
                                : sweep_reference_budget(SweepOptions{}, v.scene);
      m.truth = reference_render(v.scene, paths, ReferenceMode::kRgb);
    }
    ImageRGB image = render_scene_with(v.scene, d.choice);
    auto e = debiased_error(image, m.truth->image, m.truth->noise, sun_disk_mask(v.scene));
    double worst = 0, high = 0, noise = 0;
    for (const DebiasedError& x : e) {
      worst = std::max(worst, x.relative(x.debiased_rmse));
      high = std::max(high, x.relative(x.high));
      noise = std::max(noise, x.relative(std::sqrt(std::max(
                                  x.rmse * x.rmse - x.debiased_rmse * x.debiased_rmse, 0.0))));
    }
    m.measured[d.choice] = {{worst, high}, noise};
  }
  c.measured_error = m.measured[d.choice].first[0];
  c.measured_high = m.measured[d.choice].first[1];
  c.reference_noise = m.measured[d.choice].second;
  if (!v.held_out) {
    // The exhaustive table's cheapest within budget, by the same cost.
    for (const Prediction& p : table) {
      if (p.error <= budget / 100.0) {
        c.cheapest = p.choice;
        c.cheapest_cost_ms = p.cost_ms;
        break;
      }
    }
  }
  return c;
}

}  // namespace

std::vector<GovernorCheck> run_governor_check(
    const GovernorCheckOptions& o,
    const std::function<void(int, int, const std::string&)>& progress) {
  const ErrorModel model = load_model(o);
  const std::vector<View> all = views(o, model);
  // A check per (view, budget), kept in OUT/views/<budget>/<view>.json; a
  // view's checks share its ground truth and draws.
  std::vector<JobCell> plan;
  for (const View& v : all) {
    for (double budget : o.budgets) {
      plan.push_back({fmt::format("views/{:g}/{}.json", budget, v.scene.name),
                      fmt::format("{} at {:g} %", v.scene.name, budget), v.scene.name,
                      plan.size()});
    }
  }
  JobOptions options;
  options.redo = o.redo;
  const Job job(o.out, plan, options);
  std::vector<GovernorCheck> checks;
  ViewMeasures measures;
  JobSteps steps;
  steps.progress = progress;
  steps.keep = [&](const JobCell&, const std::filesystem::path& file) {
    std::ifstream in(file);
    try {
      checks.push_back(check_from_json(nlohmann::json::parse(in)));
      return true;
    } catch (const std::exception&) {
      return false;  // not whole: measured again
    }
  };
  steps.prepare = [&](const JobCell&) { measures = {}; };
  steps.run = [&](const JobCell& cell) {
    const View& v = all[cell.index / o.budgets.size()];
    checks.push_back(check_view(model, o, v, o.budgets[cell.index % o.budgets.size()], measures));
    return check_to_json(checks.back()).dump(2) + "\n";
  };
  job.run(steps);
  return checks;
}

std::string write_governor_check(const GovernorCheckOptions& o,
                                 const std::vector<GovernorCheck>& checks) {
  nlohmann::json j = {{"frames_per_model", o.frames_per_model}, {"checks", nlohmann::json::array()}};
  std::string csv =
      "budget_percent,view,held_out,choice,predicted_error,measured_error,measured_high,"
      "reference_noise,cost_ms,cheapest,cheapest_cost_ms,within_budget\n";
  for (const GovernorCheck& c : checks) {
    j["checks"].push_back(check_to_json(c));
    csv += fmt::format("{:g},{},{},\"{}\",{:.6f},{:.6f},{:.6f},{:.6f},{:.3f},\"{}\",{:.3f},{}\n",
                       c.budget_percent, c.view, c.held_out ? 1 : 0, c.choice, c.predicted_error,
                       c.measured_error, c.measured_high, c.reference_noise, c.cost_ms, c.cheapest,
                       c.cheapest_cost_ms, c.within_budget() ? 1 : 0);
  }
  std::string summary;
  for (double budget : o.budgets) {
    int scenes = 0, scenes_within = 0, scenes_cheap = 0, scenes_none = 0;
    // Held out: where the ground truth is good enough to tell (its noise
    // within the budget), those the governor said it met, and those it
    // said nothing meets.
    int held = 0, held_within = 0, held_uncertain = 0, held_none = 0, held_none_right = 0;
    std::string misses;
    for (const GovernorCheck& c : checks) {
      if (c.budget_percent != budget) continue;
      if (!c.held_out && c.cheapest.empty()) {
        // Nothing in the table meets the budget there: the most accurate drew.
        ++scenes_none;
        misses += fmt::format("    {}: nothing meets {:g} %; {} drew, measured {:.2f} %\n", c.view,
                              budget, c.choice, 100 * c.measured_error);
      } else if (!c.held_out) {
        ++scenes;
        scenes_within += c.within_budget() ? 1 : 0;
        bool cheap = c.cost_ms <= 1.10 * c.cheapest_cost_ms;
        scenes_cheap += cheap ? 1 : 0;
        if (!c.within_budget() || !cheap) {
          misses += fmt::format("    {}: {} measured {:.2f} %, {:.1f} ms against {} {:.1f} ms\n",
                                c.view, c.choice, 100 * c.measured_error, c.cost_ms,
                                c.cheapest.empty() ? "none within" : c.cheapest,
                                c.cheapest_cost_ms);
        }
      } else if (c.reference_noise * 100.0 > budget) {
        ++held_uncertain;
      } else if (c.predicted_error > budget / 100.0) {
        ++held_none;
        held_none_right += c.within_budget() ? 0 : 1;
      } else {
        ++held;
        held_within += c.within_budget() ? 1 : 0;
        if (!c.within_budget()) {
          misses += fmt::format("    held out {}: {} predicted {:.2f} %, measured {:.2f} % "
                                "(its ground truth's noise {:.2f} %)\n",
                                c.view, c.choice, 100 * c.predicted_error,
                                100 * c.measured_error, 100 * c.reference_noise);
        }
      }
    }
    summary += fmt::format(
        "budget {:g} %: of the {} canonical scenes where a choice meets it, {} within budget "
        "measured, {} within 10 % of the cheapest that meets it ({} where none does); held-out "
        "views where it chose within budget: {}/{} measured within ({:.1f} %); {} where it "
        "said nothing meets it ({} rightly); {} left out, their ground truth noisier than the "
        "budget\n{}",
        budget, scenes, scenes_within, scenes_cheap, scenes_none, held_within, held,
        held ? 100.0 * held_within / held : 0.0, held_none, held_none_right, held_uncertain,
        misses);
  }
  j["summary"] = summary;
  write_file_atomically(o.out / "governor.json", j.dump(2) + "\n");
  write_file_atomically(o.out / "governor.csv", csv);
  return summary;
}

}  // namespace planet
