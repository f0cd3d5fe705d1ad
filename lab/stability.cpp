#include "lab/stability.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/job.h"
#include "core/tone_map.h"
#include "core/version.h"
#include "lab/accuracy.h"
#include "lab/debiased_error.h"
#include "lab/reference_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

namespace planet {

namespace {

// "1e+04" is no name for a file: 10000, 1e4, 0.95, -0.5.
std::string short_number(double x) {
  std::string s = fmt::format("{:g}", x);
  auto e = s.find("e+");
  if (e != std::string::npos) s.erase(e + 1, 1);
  auto z = s.find("e0");
  if (z != std::string::npos) s.erase(z + 1, 1);
  return s;
}

struct Preset {
  double lat_deg;
  double mie_g;
  double bottom_radius, thickness;
  double rayleigh_scale_height;
};

Preset preset_of(const std::string& body_name) {
  Body body = load_body(find_body_file(body_name));
  AtmosphereModel m = load_atmosphere(body);
  double H = -1.0 / m.rayleigh.density.layers[1].exp_scale;
  return {body_name == "mars" ? 20.0 : 45.0, m.mie_g, m.bottom_radius,
          m.top_radius - m.bottom_radius, H};
}

const Preset& cached_preset(const std::string& body) {
  static std::map<std::string, Preset> presets;
  auto it = presets.find(body);
  if (it == presets.end()) it = presets.emplace(body, preset_of(body)).first;
  return it->second;
}


StabilityPoint point_on(StabilityPoint p, const std::string& axis, double v) {
  if (axis == "density") p.density = v;
  if (axis == "g") p.mie_g = v;
  if (axis == "radius" || axis == "radius_absolute") {
    p.bottom_radius = v;
    p.absolute_thickness = axis == "radius_absolute";
  }
  if (axis == "scale_height") p.scale_height = v;
  if (axis == "altitude") p.altitude_m = v;
  if (axis == "sun") p.sun_elevation_deg = v;
  return p;
}

const char* const kClassNames[] = {"ok", "inaccurate", "nan", "exploded", "failed"};

StabilityClass class_from(const std::string& name, const std::string& file) {
  for (int i = 0; i < 5; ++i) {
    if (name == kClassNames[i]) return StabilityClass(i);
  }
  throw InputError(fmt::format("{}: '{}' is not a class of the stability map", file, name));
}

}  // namespace

std::string to_string(StabilityClass c) { return kClassNames[int(c)]; }

std::string StabilityPoint::label() const {
  std::string s;
  auto add = [&](const std::string& part) { s += (s.empty() ? "" : "-") + part; };
  if (density != 1.0) add("d" + short_number(density));
  if (mie_g) add("g" + short_number(*mie_g));
  if (bottom_radius) add((absolute_thickness ? "ra" : "r") + short_number(*bottom_radius));
  if (scale_height != 1.0) add("h" + short_number(scale_height));
  if (altitude_m != 2.0) add("z" + short_number(altitude_m));
  if (sun_elevation_deg != 60.0) add("s" + short_number(sun_elevation_deg));
  return s.empty() ? "preset" : s;
}

nlohmann::json StabilityPoint::to_json() const {
  return {{"density", density},
          {"mie_g", mie_g ? nlohmann::json(*mie_g) : nlohmann::json()},
          {"bottom_radius_m", bottom_radius ? nlohmann::json(*bottom_radius) : nlohmann::json()},
          {"absolute_thickness", absolute_thickness},
          {"scale_height", scale_height},
          {"altitude_m", altitude_m},
          {"sun_elevation_deg", sun_elevation_deg}};
}

namespace {

StabilityPoint point_from_json(const nlohmann::json& j) {
  StabilityPoint p;
  p.density = j.at("density").get<double>();
  if (!j.at("mie_g").is_null()) p.mie_g = j.at("mie_g").get<double>();
  if (!j.at("bottom_radius_m").is_null()) p.bottom_radius = j.at("bottom_radius_m").get<double>();
  p.absolute_thickness = j.at("absolute_thickness").get<bool>();
  p.scale_height = j.at("scale_height").get<double>();
  p.altitude_m = j.at("altitude_m").get<double>();
  p.sun_elevation_deg = j.at("sun_elevation_deg").get<double>();
  return p;
}

}  // namespace

const std::vector<std::string>& stability_bodies() {
  static const std::vector<std::string> bodies{"earth", "mars", "asteroid"};
  return bodies;
}

std::vector<StabilityAxis> stability_axes(const std::string& body) {
  (void)body;
  return {
      {"density", "density scale (scattering and absorption) x", {0.1, 0.3, 3, 10, 20, 30, 50, 100}},
      {"g", "Mie asymmetry g", {-0.5, 0, 0.5, 0.9, 0.95, 0.99}},
      {"radius", "bottom radius (m), at the preset's thickness ratio", {1e4, 1e5, 1e6, 1e7, 7e7}},
      {"radius_absolute", "bottom radius (m), at the preset's thickness", {1e4, 1e5, 1e6, 1e7, 7e7}},
      {"scale_height", "scale heights x (their optical depth kept)", {0.25, 0.5, 2, 4, 10}},
      {"altitude", "camera altitude (m)", {-1000, 1, 100, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9}},
      {"sun", "sun elevation (deg)", {-20, -10, -4, 0, 2, 5, 10, 30, 90}},
  };
}

Scene stability_scene(const std::string& body, const StabilityPoint& p, int width, int height) {
  const Preset& preset = cached_preset(body);
  Scene s;
  s.name = "stability-" + body + "-" + p.label();
  s.description = fmt::format("the stability map's {} cell {}", body, p.label());
  s.body = body;
  s.width = width;
  s.height = height;
  s.scattering_scale = p.density;
  s.absorption_scale = p.density;
  s.mie_g = p.mie_g;
  s.bottom_radius = p.bottom_radius;
  s.absolute_thickness = p.absolute_thickness;
  s.scale_height_scale = p.scale_height;
  s.exposure = p.density > 3 ? 5.0 : 10.0;
  // The shell's angular radius from the camera decides the view.
  double k = p.bottom_radius ? *p.bottom_radius / preset.bottom_radius : 1.0;
  double bottom = preset.bottom_radius * k;
  double top = bottom + (p.absolute_thickness ? 1.0 : k) * preset.thickness;
  double alpha = glm::degrees(std::asin(std::min(1.0, top / (bottom + std::max(p.altitude_m, 0.0)))));
  ScenePlacement place;
  place.lat_deg = preset.lat_deg;
  place.height_m = p.altitude_m;
  place.sun_elevation_deg = p.sun_elevation_deg;
  place.sun_azimuth_deg = 30.0;
  if (alpha >= 45.0) {
    // Above the lowest hundredth of the air, the horizon kept where it is
    // from the ground, 35 degrees below the middle, as it dips: from the
    // top of the air the sky above is black and the light is at the limb.
    double dip = p.altitude_m > 0.01 * (top - bottom)
                     ? glm::degrees(std::acos(bottom / (bottom + p.altitude_m)))
                     : 0.0;
    place.pitch_deg = 35.0 - dip;
    place.vertical_fov_deg = 90.0;
  } else {
    place.pitch_deg = -90.0;
    place.vertical_fov_deg = std::min(90.0, 2.6 * alpha);
  }
  return placed(s, place);
}

std::filesystem::path stability_result_file(const StabilityOptions& o, const std::string& cell,
                                            const std::string& technique,
                                            const std::string& quality) {
  return o.out / "cells" / cell / (technique + "-" + quality + ".json");
}

std::vector<StabilityCell> plan_stability(const StabilityOptions& o) {
  if (!(o.budget_percent > 0 && o.budget_percent < 1000)) {
    throw InputError(fmt::format("lab stability --budget: {} is not a percentage above 0",
                                 o.budget_percent));
  }
  if (!(o.time_limit_s > 0)) {
    throw InputError(fmt::format("lab stability --time-limit: {} is not a time above 0 s",
                                 o.time_limit_s));
  }
  if (o.shards < 1 || o.shard < 1 || o.shard > o.shards) {
    throw InputError(fmt::format("lab stability --shard: {}/{} is not K/N with 1 <= K <= N",
                                 o.shard, o.shards));
  }
  std::vector<std::string> bodies = o.bodies.empty() ? stability_bodies() : o.bodies;
  for (const std::string& b : bodies) {
    const auto& known = stability_bodies();
    if (std::find(known.begin(), known.end(), b) == known.end()) {
      throw InputError(
          fmt::format("lab stability --bodies: '{}' is not one of {}", b, fmt::join(known, ", ")));
    }
  }
  std::vector<StabilityCell> cells;
  std::map<std::string, size_t> index;
  auto add = [&](const std::string& body, const StabilityPoint& p, const std::string& slice) {
    std::string name = "stability-" + body + "-" + p.label();
    auto it = index.find(name);
    if (it != index.end()) {
      auto& slices = cells[it->second].slices;
      if (std::find(slices.begin(), slices.end(), slice) == slices.end()) slices.push_back(slice);
      return;
    }
    index[name] = cells.size();
    cells.push_back({body, p, {slice}, stability_scene(body, p, o.width, o.height)});
  };
  for (const std::string& body : bodies) {
    StabilityPoint preset;
    for (const StabilityAxis& axis : stability_axes(body)) {
      add(body, preset, axis.name);
      for (double v : axis.values) add(body, point_on(preset, axis.name, v), axis.name);
    }
    for (double d : {0.1, 1.0, 10.0, 100.0}) {
      for (double g : {-0.5, 0.5, 0.9, 0.99}) {
        add(body, point_on(point_on(preset, "density", d), "g", g), "density_g");
      }
    }
    for (double r : {1e4, 1e5, 1e6, 1e7, 7e7}) {
      for (double z : {1.0, 1e4, 1e6, 1e8}) {
        add(body, point_on(point_on(preset, "radius", r), "altitude", z), "radius_altitude");
      }
    }
  }
  return cells;
}

std::vector<StabilityCell> shard_cells(const std::vector<StabilityCell>& cells, int shard,
                                       int shards) {
  std::vector<StabilityCell> out;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (share_owns({shard - 1, shards}, ShareSplit::kInterleaved, int(i), int(cells.size()))) {
      out.push_back(cells[i]);
    }
  }
  return out;
}

std::vector<StabilityCell> named_cells(const std::vector<StabilityCell>& cells,
                                       const std::vector<std::string>& names) {
  if (names.empty()) return cells;
  std::vector<StabilityCell> out;
  for (const std::string& name : names) {
    auto it = std::find_if(cells.begin(), cells.end(),
                           [&](const StabilityCell& c) { return c.scene.name == name; });
    if (it == cells.end()) {
      throw InputError(fmt::format("lab stability --cells: '{}' is not a cell of the map (its "
                                   "cells are named stability-BODY-LABEL, e.g. "
                                   "stability-earth-d50; --list shows them all)",
                                   name));
    }
    out.push_back(*it);
  }
  return out;
}

std::pair<int, int> parse_shard(const std::string& text) {
  int k = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &extra) != 3 || slash != '/' ||
      n < 1 || k < 1 || k > n) {
    throw InputError(fmt::format(
        "lab stability --shard: '{}' is not K/N (this machine's part K of N, 1 <= K <= N)", text));
  }
  return {k, n};
}

PathBudget stability_reference_budget(const StabilityCell& cell) {
  // Paths in dense air scatter many times: fewer of them, their noise
  // taken out of the error.
  // Strong forward scattering: a path's turn toward the sun weighs up to
  // (1 + g) / (1 - g)^2 times an isotropic one's, rare and bright; more of
  // them.
  int spp = cell.point.density >= 30   ? 256
            : cell.point.density >= 10 ? 512
            : cell.point.mie_g && *cell.point.mie_g >= 0.95 ? 4096
                                                           : 1024;
  return PathBudget(spp);
}

double stability_reference_seconds(const StabilityCell& cell) {
  // 16x8 at 1024 paths: a few seconds in thin air; paths in dense air
  // scatter many more times.
  return 4.0 * stability_reference_budget(cell).spp / 1024.0 *
         std::max(1.0, cell.point.density / 3.0);
}

double StabilityResult::worst() const {
  if (std::isnan(error[0])) return error[0];  // no ground truth
  return std::max({error[0], error[1], error[2]});
}

namespace {

// JSON has no NaN: null stands for "not measured".
nlohmann::json measured(double x) { return std::isnan(x) ? nlohmann::json() : nlohmann::json(x); }
nlohmann::json measured(const std::array<double, 3>& v) {
  return {measured(v[0]), measured(v[1]), measured(v[2])};
}
double measured_from(const nlohmann::json& j) {
  return j.is_null() ? std::nan("") : j.get<double>();
}
std::array<double, 3> measured3_from(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3) throw nlohmann::json::type_error::create(302, "not 3 numbers", &j);
  return {measured_from(j[0]), measured_from(j[1]), measured_from(j[2])};
}

}  // namespace

StabilityResult classify(const Scene& scene, const ImageRGB& image, const ImageRGB* reference,
                         const ImageRGB* noise, double budget_percent) {
  StabilityResult r;
  std::vector<uint8_t> sun = sun_disk_mask(scene);
  const int w = image.width;
  int non_finite = 0, first_bad = -1;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    if (!std::isfinite(image.pixels[i])) {
      ++non_finite;
      if (first_bad < 0) first_bad = int(i / 3);
    }
  }
  if (non_finite > 0) {
    r.cls = StabilityClass::kNaN;
    r.reason = fmt::format("{} of {} values not finite, the first at pixel ({}, {})", non_finite,
                           image.pixels.size(), first_bad % w, first_bad / w);
    return r;
  }
  // Radiance below a hundred-thousandth of the sun's irradiance is dark at
  // any exposure that shows a day sky: the floor of every ratio below, so
  // that a sky with next to nothing in it (the sun far below the horizon)
  // is not judged by the ratio of two next-to-nothings.
  glm::dvec3 floor = 1e-5 * scene_atmosphere(scene, scene_body(scene)).solar_irradiance;
  static const char* const kChannel[] = {"red", "green", "blue"};
  std::array<double, 3> mean{};
  if (reference) mean = masked_mean(*reference, sun);
  for (size_t i = 0; i < sun.size(); ++i) {
    if (sun[i]) continue;
    for (size_t c = 0; c < 3; ++c) {
      double t = image.pixels[i * 3 + c];
      double low = std::max(1e-3 * mean[c], floor[int(c)]);
      if (r.cls == StabilityClass::kOk && t < -low) {
        r.cls = StabilityClass::kExploded;
        r.reason = fmt::format("{} {:.3g} below zero at pixel ({}, {})", kChannel[c], t,
                               int(i) % w, int(i) / w);
      }
      if (!reference) continue;
      // Over ten times its reference's value, the reference's noise allowed for.
      double ref = std::max(reference->pixels[i * 3 + c] + 3.0 * noise->pixels[i * 3 + c], low);
      double ratio = t / ref;
      r.worst_ratio = std::max(r.worst_ratio, ratio);
      if (r.cls == StabilityClass::kOk && ratio > 10.0) {
        r.cls = StabilityClass::kExploded;
        r.reason = fmt::format("{} {:.3g} is {:.3g}x the reference's {:.3g} at pixel ({}, {})",
                               kChannel[c], t, ratio, reference->pixels[i * 3 + c], int(i) % w,
                               int(i) / w);
      }
    }
  }
  if (!reference) {
    for (double& e : r.error) e = std::nan("");
    r.low = r.high = r.error;
    if (r.cls == StabilityClass::kOk) {
      r.reason = "no ground truth (the camera is inside the planet): checked for values not "
                 "finite or below zero only";
    }
    return r;
  }
  std::array<DebiasedError, 3> e = debiased_error(image, *reference, *noise, sun);
  std::array<double, 3> noise_rms = masked_rms(*noise, sun);
  for (size_t c = 0; c < 3; ++c) {
    double over = std::max(mean[c], floor[int(c)]);
    r.error[c] = e[c].debiased_rmse / over;
    r.low[c] = e[c].low / over;
    r.high[c] = e[c].high / over;
    r.reference_noise = std::max(r.reference_noise, noise_rms[c] / over);
  }
  if (r.cls == StabilityClass::kOk && r.worst() * 100.0 > budget_percent) {
    r.cls = StabilityClass::kInaccurate;
    r.reason = fmt::format("{:.3g} % over the {:g} % budget", 100.0 * r.worst(), budget_percent);
  }
  if (r.reference_noise * 100.0 > budget_percent) {
    r.reason += fmt::format("{}the ground truth's noise is {:.3g} %, over the budget: the class "
                            "is uncertain",
                            r.reason.empty() ? "" : "; ", 100.0 * r.reference_noise);
  }
  return r;
}

nlohmann::json result_to_json(const StabilityResult& r) {
  return {{"cell", r.cell},
          {"body", r.body},
          {"technique", r.technique},
          {"quality", r.quality},
          {"choice", r.choice},
          {"point", r.point.to_json()},
          {"slices", r.slices},
          {"class", to_string(r.cls)},
          {"reason", r.reason},
          {"error", measured(r.error)},
          {"low", measured(r.low)},
          {"high", measured(r.high)},
          {"worst", measured(r.worst())},
          {"worst_ratio", r.worst_ratio},
          {"render_s", r.render_s},
          {"reference_noise", r.reference_noise}};
}

StabilityResult result_from_json(const nlohmann::json& json, const std::string& file) {
  return read_job_json(json, file, "planet lab stability", [&](const nlohmann::json& j) {
    StabilityResult r;
    r.cell = j.at("cell").get<std::string>();
    r.body = j.at("body").get<std::string>();
    r.technique = j.at("technique").get<std::string>();
    r.quality = j.at("quality").get<std::string>();
    r.choice = j.at("choice").get<std::string>();
    r.point = point_from_json(j.at("point"));
    r.slices = j.at("slices").get<std::vector<std::string>>();
    r.cls = class_from(j.at("class").get<std::string>(), file);
    r.reason = j.at("reason").get<std::string>();
    r.error = measured3_from(j.at("error"));
    r.low = measured3_from(j.at("low"));
    r.high = measured3_from(j.at("high"));
    r.worst_ratio = j.at("worst_ratio").get<double>();
    r.render_s = j.at("render_s").get<double>();
    r.reference_noise = j.at("reference_noise").get<double>();
    return r;
  });
}

StabilityResult read_stability_result(const std::filesystem::path& file) {
  return result_from_json(read_job_file(file, "planet lab stability"), file.string());
}

void write_stability_tables(const StabilityOptions& o, const std::vector<StabilityResult>& results) {
  nlohmann::json bodies = nlohmann::json::object();
  for (const std::string& body : stability_bodies()) {
    const Preset& p = cached_preset(body);
    nlohmann::json axes = nlohmann::json::array();
    for (const StabilityAxis& a : stability_axes(body)) {
      axes.push_back({{"name", a.name}, {"label", a.label}, {"values", a.values}});
    }
    bodies[body] = {{"mie_g", p.mie_g},
                    {"bottom_radius_m", p.bottom_radius},
                    {"thickness_m", p.thickness},
                    {"scale_height_over_thickness", p.rayleigh_scale_height / p.thickness},
                    {"altitude_m", 2.0},
                    {"sun_elevation_deg", 60.0},
                    {"axes", axes}};
  }
  std::map<std::string, int> counts;
  for (const StabilityResult& r : results) ++counts[to_string(r.cls)];
  nlohmann::json j = {
      {"planet", planet_version()},
      {"budget_percent", o.budget_percent},
      {"time_limit_s", o.time_limit_s},
      {"size", {o.width, o.height}},
      {"error", "the worst channel's relative RMSE against the cell's ground truth, its noise "
                "taken out (a fraction)"},
      {"classes", "ok: within the budget; inaccurate: over it; nan: a value not finite; "
                  "exploded: a value below zero or over 10x its reference's; failed: an error, "
                  "or over the time limit"},
      {"counts", counts},
      {"bodies", bodies},
      {"results", nlohmann::json::array()}};
  std::string csv =
      "cell,body,technique,quality,choice,density,mie_g,bottom_radius_m,absolute_thickness,"
      "scale_height,altitude_m,sun_elevation_deg,slices,class,error,error_r,error_g,error_b,"
      "worst_ratio,render_s,reference_noise,reason\n";
  auto optional = [](const std::optional<double>& v) {
    return v ? fmt::format("{:g}", *v) : std::string();
  };
  for (const StabilityResult& r : results) {
    j["results"].push_back(result_to_json(r));
    std::string slices;
    for (const std::string& s : r.slices) slices += (slices.empty() ? "" : " ") + s;
    std::string reason = r.reason;
    std::replace(reason.begin(), reason.end(), '"', '\'');
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    csv += fmt::format("{},{},{},{},\"{}\",{:g},{},{},{},{:g},{:g},{:g},{},{},{:.6f},{:.6f},{:.6f},"
                       "{:.6f},{:.4g},{:.3f},{:.5f},\"{}\"\n",
                       r.cell, r.body, r.technique, r.quality, r.choice, r.point.density,
                       optional(r.point.mie_g), optional(r.point.bottom_radius),
                       r.point.absolute_thickness ? 1 : 0, r.point.scale_height, r.point.altitude_m,
                       r.point.sun_elevation_deg, slices, to_string(r.cls), r.worst(), r.error[0],
                       r.error[1], r.error[2], r.worst_ratio, r.render_s, r.reference_noise, reason);
  }
  write_file_atomically(o.out / "stability.json", j.dump(2) + "\n");
  write_file_atomically(o.out / "stability.csv", csv);
}

}  // namespace planet
