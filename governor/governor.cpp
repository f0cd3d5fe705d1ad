#include "governor/governor.h"

#include "atmosphere/atmosphere_space.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/json_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>

namespace planet {

namespace {

constexpr const char* kFormat = "planet-error-model-1";

double vertical_optical_depth(const AtmosphereModel& model) {
  // The midpoint rule on 2000 layers: within 1e-4 of the integral for
  // every shipped profile, and cheap enough for every frame.
  constexpr int kLayers = 2000;
  const double thickness = model.top_radius - model.bottom_radius;
  const double dh = thickness / kLayers;
  double tau = 0;
  for (int i = 0; i < kLayers; ++i) {
    double h = (i + 0.5) * dh;
    for (const AtmosphereComponent* c : {&model.rayleigh, &model.mie, &model.absorber}) {
      tau += c->extinction().y * density_at(c->density, h) * dh;
    }
  }
  return tau;
}

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

ViewFeatures parse_view(JsonObject o) {
  ViewFeatures v;
  v.body = o.string("body");
  v.altitude_m = o.number("altitude_m", -1e12, 1e15);
  v.shell_m = o.number("shell_m", 1e-3, 1e12);
  v.sun_elevation_deg = o.number("sun_elevation_deg", -90, 90);
  v.optical_depth = o.number("optical_depth", 0, 1e6);
  v.mie_g = o.number("mie_g", -1, 1);
  v.bottom_radius_m = o.number("bottom_radius_m", 1e-3, 1e12);
  o.finish();
  return v;
}

nlohmann::json view_json(const ViewFeatures& v) {
  return {{"body", v.body},
          {"altitude_m", v.altitude_m},
          {"shell_m", v.shell_m},
          {"sun_elevation_deg", v.sun_elevation_deg},
          {"optical_depth", v.optical_depth},
          {"mie_g", v.mie_g},
          {"bottom_radius_m", v.bottom_radius_m}};
}

nlohmann::json prediction_json(const Prediction& p) {
  return {{"choice", p.choice},
          {"error_percent", 100.0 * p.error},
          {"frame_ms", p.frame_ms},
          {"cost_ms", p.cost_ms}};
}

}  // namespace

ViewFeatures view_features(const Body& body, const AtmosphereModel& model,
                           const glm::dvec3& camera_pos_body, const glm::dvec3& sun_dir_body) {
  const glm::dvec3 scale = atmosphere_scale(body.shape, model.bottom_radius);
  const glm::dvec3 camera = scale * camera_pos_body;
  const glm::dvec3 sun = glm::normalize(scale * sun_dir_body);
  const double r = glm::length(camera);
  ViewFeatures v;
  v.body = body.name;
  v.altitude_m = r - model.bottom_radius;
  v.shell_m = model.top_radius - model.bottom_radius;
  v.sun_elevation_deg =
      r > 0 ? glm::degrees(std::asin(std::clamp(glm::dot(camera / r, sun), -1.0, 1.0))) : 90.0;
  v.optical_depth = vertical_optical_depth(model);
  v.mie_g = model.mie_g;
  v.bottom_radius_m = model.bottom_radius;
  return v;
}

double view_distance(const ViewFeatures& a, const ViewFeatures& b) {
  if (a.body != b.body) return std::numeric_limits<double>::infinity();
  // Heights in shell thicknesses above the ground, on a log scale that is
  // flat near the ground: 2 m and 10 km are one class on Earth, 400 km and
  // 40 000 km are not.
  auto height = [](const ViewFeatures& v) {
    return std::log10(1.0 + std::max(v.altitude_m, 0.0) / v.shell_m);
  };
  double d_height = (height(a) - height(b)) / 0.15;
  double d_sun = (a.sun_elevation_deg - b.sun_elevation_deg) / 10.0;
  double d_tau = std::log(std::max(a.optical_depth, 1e-9) / std::max(b.optical_depth, 1e-9)) /
                 std::log(3.0);
  double d_g = (a.mie_g - b.mie_g) / 0.1;
  double d_radius = std::log10(a.bottom_radius_m / b.bottom_radius_m);
  return std::sqrt(d_height * d_height + d_sun * d_sun + d_tau * d_tau + d_g * d_g +
                   d_radius * d_radius);
}

ErrorModel parse_error_model(const nlohmann::json& json, const std::string& where) {
  JsonObject root(json, where, "");
  std::string format = root.string("format");
  if (format != kFormat) {
    root.fail("format", fmt::format("'{}' is not {}: not an error model this program wrote",
                                    format, kFormat));
  }
  ErrorModel model;
  model.source = root.string("source");
  std::vector<double> size = root.numbers("time_size", 2, 1, 16384);
  model.time_width = int(size[0]);
  model.time_height = int(size[1]);
  JsonObject changes = root.object("model_change_ms");
  for (const auto& [choice, value] : root.raw("model_change_ms").items()) {
    model.model_change_ms[choice] = changes.number(choice, 0, 1e9);
  }
  changes.finish();
  for (JsonObject c : root.objects("classes")) {
    ViewClass vc;
    vc.scene = c.string("scene");
    vc.view = parse_view(c.object("view"));
    std::set<std::string> seen;
    for (JsonObject e : c.objects("entries")) {
      ErrorModelEntry entry;
      entry.choice = e.string("choice");
      entry.error = e.number("error", 0, 1e6);
      entry.error_high = e.number("error_high", 0, 1e6);
      entry.frame_ms = e.number("frame_ms", 0, 1e9);
      if (!seen.insert(entry.choice).second) {
        e.fail("choice", fmt::format("'{}' is listed twice", entry.choice));
      }
      e.finish();
      vc.entries.push_back(entry);
    }
    if (vc.entries.empty()) c.fail("entries", "is empty: a class needs at least one choice");
    c.finish();
    model.classes.push_back(std::move(vc));
  }
  root.finish();
  if (model.classes.empty()) root.fail("classes", "is empty: the table has no view");
  return model;
}

ErrorModel load_error_model(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(fmt::format("{}: no error model there (planet lab run writes one)",
                                 file.string()));
  }
  std::ifstream in(file);
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not JSON: {}", file.string(), e.what()));
  }
  if (!json.is_object()) throw InputError(file.string() + ": not an error model (not an object)");
  return parse_error_model(json, file.string());
}

nlohmann::json error_model_to_json(const ErrorModel& model) {
  nlohmann::json classes = nlohmann::json::array();
  for (const ViewClass& c : model.classes) {
    nlohmann::json entries = nlohmann::json::array();
    for (const ErrorModelEntry& e : c.entries) {
      entries.push_back({{"choice", e.choice},
                         {"error", e.error},
                         {"error_high", e.error_high},
                         {"frame_ms", e.frame_ms}});
    }
    classes.push_back({{"scene", c.scene}, {"view", view_json(c.view)}, {"entries", entries}});
  }
  return {{"format", kFormat},
          {"source", model.source},
          {"time_size", {model.time_width, model.time_height}},
          {"model_change_ms", model.model_change_ms},
          {"classes", classes}};
}

std::filesystem::path shipped_error_model_file() { return data_dir() / "lab" / "error_model.json"; }

double checked_error_budget(double percent, const std::string& where) {
  if (!(percent > 0.0 && percent <= 1000.0)) {
    throw InputError(
        fmt::format("{}: {} is not an error budget: a percentage above 0 and at most 1000",
                    where, percent));
  }
  return percent;
}

nlohmann::json GovernorDecision::to_json(double budget_percent) const {
  nlohmann::json j = {{"budget_percent", budget_percent},
                      {"governed", governed},
                      {"choice", choice},
                      {"why", why}};
  if (!governed) return j;
  j["predicted"] = prediction_json(chosen);
  j["within_budget"] = within_budget;
  j["cheapest_within_budget"] = prediction_json(cheapest);
  j["most_accurate"] = prediction_json(most_accurate);
  j["from_scenes"] = classes;
  j["distance"] = distance;
  if (!fading_from.empty()) {
    j["fading_from"] = fading_from;
    j["fade_weight"] = fade_weight;
  }
  return j;
}

Governor::Governor(ErrorModel model, GovernorSettings settings, std::string fallback)
    : model_(std::move(model)), settings_(settings), fallback_(std::move(fallback)) {}

std::vector<Prediction> Governor::predict(const ViewFeatures& view,
                                          std::vector<std::string>* classes,
                                          double* distance) const {
  // A body the table has: its own rows, and the other bodies' rows a
  // little further off (an atmosphere's errors follow its optical depth,
  // asymmetry, altitude and sun more than its name: a dense Mars is more
  // like a dense Earth than like Mars). A body it does not have: none.
  constexpr double kOtherBody = 1.5;
  const bool known = std::any_of(model_.classes.begin(), model_.classes.end(),
                                 [&](const ViewClass& c) { return c.view.body == view.body; });
  if (!known) return {};
  std::vector<std::pair<double, const ViewClass*>> near;
  for (const ViewClass& c : model_.classes) {
    ViewFeatures same = c.view;
    same.body = view.body;
    double d = view_distance(view, same) + (c.view.body == view.body ? 0.0 : kOtherBody);
    near.emplace_back(d, &c);
  }
  std::sort(near.begin(), near.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  // One of the lab's own views: its row alone. Elsewhere every row within
  // half a class of the nearest, or half the nearest's distance where that
  // is more, each choice at the worst of them: a view between measured ones
  // is taken to be as hard as the hardest, and the further it is from any,
  // the more of them it is taken to be as hard as.
  constexpr double kSameView = 1e-6, kNear = 0.5;
  const double nearest = near.front().first;
  const double reach = nearest < kSameView ? kSameView : nearest + std::max(kNear, 0.5 * nearest);
  std::vector<const ViewClass*> used;
  for (const auto& [d, c] : near) {
    if (d <= reach) used.push_back(c);
  }
  if (classes) {
    classes->clear();
    for (const ViewClass* c : used) classes->push_back(c->scene);
  }
  if (distance) *distance = nearest;

  std::vector<Prediction> out;
  for (const ErrorModelEntry& e : used.front()->entries) {
    Prediction p;
    p.choice = e.choice;
    p.error = e.error;
    p.frame_ms = e.frame_ms;
    bool everywhere = true;
    for (size_t k = 1; k < used.size(); ++k) {
      auto it = std::find_if(used[k]->entries.begin(), used[k]->entries.end(),
                             [&](const ErrorModelEntry& x) { return x.choice == e.choice; });
      if (it == used[k]->entries.end()) {
        everywhere = false;
        break;
      }
      p.error = std::max(p.error, it->error);
    }
    if (!everywhere) continue;
    p.cost_ms = p.frame_ms;
    auto change = model_.model_change_ms.find(e.choice);
    if (settings_.frames_per_model > 0 && change != model_.model_change_ms.end() &&
        !built_.count(e.choice)) {
      p.cost_ms += change->second / settings_.frames_per_model;
    }
    out.push_back(p);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Prediction& a, const Prediction& b) { return a.cost_ms < b.cost_ms; });
  return out;
}

GovernorDecision Governor::decide(const ViewFeatures& view) {
  GovernorDecision d;
  const double budget = settings_.budget_percent / 100.0;
  std::vector<Prediction> all = predict(view, &d.classes, &d.distance);
  auto advance_fade = [&] {
    if (fading_from_.empty()) return;
    double w = 1.0 - smoothstep(double(fade_frame_++) / std::max(settings_.fade_frames, 1));
    if (w <= 0.0) {
      fading_from_.clear();
      return;
    }
    d.fading_from = fading_from_;
    d.fade_weight = w;
  };
  if (all.empty()) {
    d.choice = current_.empty() ? fallback_ : current_;
    d.why = fmt::format("the error model has no view of {}: {} draws", view.body, d.choice);
    current_ = d.choice;
    advance_fade();
    return d;
  }
  d.governed = true;
  const Prediction* cheapest = nullptr;
  const Prediction* accurate = &all.front();
  for (const Prediction& p : all) {
    if (!cheapest && p.error <= budget) cheapest = &p;
    if (p.error < accurate->error) accurate = &p;
  }
  d.most_accurate = *accurate;
  // Nothing meets the budget: the most accurate there is.
  const Prediction& best = cheapest ? *cheapest : *accurate;
  d.cheapest = best;

  auto find = [&](const std::string& choice) -> const Prediction* {
    for (const Prediction& p : all) {
      if (p.choice == choice) return &p;
    }
    return nullptr;
  };
  const Prediction* current = current_.empty() ? nullptr : find(current_);
  std::string reason;
  if (!current) {
    current_ = best.choice;
    candidate_.clear();
    candidate_frames_ = 0;
    reason = "first choice";
    current = find(current_);
  } else if (current->choice == best.choice) {
    candidate_.clear();
    candidate_frames_ = 0;
  } else if (current->error > budget && best.error <= budget) {
    // Over budget: leave at once.
    fading_from_ = current_;
    fade_frame_ = 0;
    current_ = best.choice;
    candidate_.clear();
    candidate_frames_ = 0;
    reason = fmt::format("{} predicted {:.2f} % over budget", fading_from_, 100.0 * current->error);
    current = find(current_);
  } else if (best.cost_ms < (1.0 - settings_.switch_gain) * current->cost_ms ||
             (current->error > budget && best.error < current->error)) {
    if (candidate_ != best.choice) {
      candidate_ = best.choice;
      candidate_frames_ = 0;
    }
    if (++candidate_frames_ >= settings_.dwell_frames) {
      fading_from_ = current_;
      fade_frame_ = 0;
      current_ = best.choice;
      candidate_.clear();
      candidate_frames_ = 0;
      reason = fmt::format("{} cheaper than {} for {} frames", best.choice, fading_from_,
                           settings_.dwell_frames);
      current = find(current_);
    } else {
      reason = fmt::format("{} is cheaper; held {}/{} frames", best.choice, candidate_frames_,
                           settings_.dwell_frames);
    }
  } else {
    candidate_.clear();
    candidate_frames_ = 0;
    reason = fmt::format("kept: {} saves under {:.0f} %", best.choice,
                         100.0 * settings_.switch_gain);
  }
  d.choice = current_;
  d.chosen = *current;
  built_.insert(current_);
  d.within_budget = current->error <= budget;
  if (!fading_from_.empty() && fade_frame_ == 0) {
    // The frame of the switch shows the old one whole; the fade starts after.
    d.fading_from = fading_from_;
    d.fade_weight = 1.0;
    ++fade_frame_;
  } else {
    advance_fade();
  }
  std::string scenes;
  for (const std::string& s : d.classes) scenes += (scenes.empty() ? "" : "+") + s;
  d.why = fmt::format("{}: {:.2f} % predicted (budget {:g} %) at {:.1f} ms, from {}{}{}",
                      d.choice, 100.0 * d.chosen.error, settings_.budget_percent,
                      d.chosen.cost_ms, scenes,
                      d.within_budget ? "" : "; nothing meets the budget, the most accurate",
                      reason.empty() ? "" : "; " + reason);
  return d;
}

}  // namespace planet
