#include "lab/gpu/clarity_run.h"

#include "atmosphere/gpu/registry.h"
#include "core/error.h"
#include "lab/gpu/scene_render.h"

#include <fmt/format.h>

#include <cmath>

namespace planet {

std::vector<Scene> clarity_plan(const ClarityOptions& options) {
  for (const std::string& t : options.techniques) parse_technique(t);  // fails on a bad name
  if (options.ground_paths < 1) {
    throw InputError(fmt::format("--ground-paths: {} is not a count of paths (1 or more)",
                                 options.ground_paths));
  }
  if (options.views.empty()) return clarity_views();
  std::vector<Scene> views;
  for (const std::string& name : options.views) views.push_back(find_clarity_view(name));
  return views;
}

void measure_drawing(const std::vector<ClarityRow>& rows, ClarityDrawing& drawing) {
  drawing.contrast.assign(rows.size(), glm::dvec3(0.0));
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].ground) drawing.contrast[i] = contrast(rows[i], drawing.dark, drawing.bright);
  }
  for (int c = 0; c < 3; ++c) {
    std::vector<double> channel(rows.size());
    for (size_t i = 0; i < rows.size(); ++i) channel[i] = drawing.contrast[i][c];
    drawing.visibility_m[c] = visibility_range(rows, channel, drawing.at_horizon[c]);
  }
}

namespace {

ClarityDrawing model_drawing(const std::vector<ClarityRow>& rows) {
  ClarityDrawing d;
  d.name = "model";
  d.contrast.assign(rows.size(), glm::dvec3(0.0));
  for (int c = 0; c < 3; ++c) {
    std::vector<double> t = model_transmittance(rows, c);
    for (size_t i = 0; i < rows.size(); ++i) d.contrast[i][c] = t[i];
    d.visibility_m[c] = visibility_range(rows, t, d.at_horizon[c]);
  }
  return d;
}

}  // namespace

std::vector<ClarityResult> run_clarity(const ClarityOptions& options,
                                       const std::function<ImageRGB(const Scene&)>& truth) {
  std::vector<std::string> techniques = options.techniques;
  if (techniques.empty()) techniques = technique_names();
  std::vector<ClarityResult> results;
  for (const Scene& view : clarity_plan(options)) {
    ClarityResult r;
    r.view = view;
    r.rows = clarity_rows(view, options.ground_paths, options.uniform);
    r.model = model_drawing(r.rows);
    r.truth.name = "truth";
    r.truth.dark = truth(clarity_scene(view, kClarityDarkAlbedo, options.uniform));
    r.truth.bright = truth(clarity_scene(view, kClarityBrightAlbedo, options.uniform));
    measure_drawing(r.rows, r.truth);
    for (const std::string& t : techniques) {
      ClarityDrawing d;
      d.name = t;
      d.dark = render_scene_with(clarity_scene(view, kClarityDarkAlbedo, options.uniform), t);
      d.bright = render_scene_with(clarity_scene(view, kClarityBrightAlbedo, options.uniform), t);
      measure_drawing(r.rows, d);
      r.techniques.push_back(std::move(d));
    }
    const Body body = scene_body(view);
    const AtmosphereModel model = scene_atmosphere(view, body);
    double eye = glm::length(reference_view(view, body, model).camera_atmo) - model.bottom_radius;
    r.koschmieder_eye_m = koschmieder_visibility(model, eye);
    r.koschmieder_ground_m = koschmieder_visibility(model, 0.0);
    r.uniform = options.uniform;
    r.ground_albedo = model.ground_albedo.g;
    results.push_back(std::move(r));
  }
  return results;
}

namespace {

std::string visibility_text(const ClarityDrawing& d, int c) {
  if (d.visibility_m[c] >= 0.0) return fmt::format("{:.0f} km", d.visibility_m[c] / 1e3);
  return fmt::format("beyond the horizon ({:.3f} there)", d.at_horizon[c]);
}

}  // namespace

std::string clarity_text(const std::vector<ClarityResult>& results) {
  std::string out;
  for (const ClarityResult& r : results) {
    out += r.uniform ? fmt::format("{}: {}; uniform grounds of albedo {} and {}\n", r.view.name,
                                   r.view.description, kClarityDarkAlbedo, kClarityBrightAlbedo)
                     : fmt::format("{}: {}; targets of albedo {} and {} on the ground's {}\n",
                                   r.view.name, r.view.description, kClarityDarkAlbedo,
                                   kClarityBrightAlbedo, r.ground_albedo);
    // Above the air's top (the eye at 400 km) there is no level path to
    // speak of: the ground's figure alone.
    const glm::dvec3& eye = r.koschmieder_eye_m;
    std::string at_eye = eye.b < 1e9 ? fmt::format("{:.0f} {:.0f} {:.0f} km at the eye, ",
                                                   eye.r / 1e3, eye.g / 1e3, eye.b / 1e3)
                                     : std::string();
    out += fmt::format(
        "  Koschmieder's visibility ln(50)/sigma (R G B): {}{:.0f} {:.0f} {:.0f} km "
        "at the ground\n",
        at_eye, r.koschmieder_ground_m.r / 1e3, r.koschmieder_ground_m.g / 1e3,
        r.koschmieder_ground_m.b / 1e3);
    out +=
        "  contrast (L_bright - L_dark) / (L0_bright - L0_dark), green, beside the model's "
        "exp(-tau)\n";
    std::string head =
        fmt::format("  {:>9} {:>8} {:>7} {:>7}", "range km", "down deg", "model", "truth");
    for (const ClarityDrawing& d : r.techniques) head += fmt::format(" {:>12}", d.name);
    out += head + "\n";
    int last = -1;
    for (const ClarityRow& row : r.rows) last = row.ground ? row.row : last;
    for (const ClarityRow& row : r.rows) {
      if (!row.ground || (row.row % 4 != 3 && row.row != last)) continue;
      size_t i = size_t(row.row);
      std::string line =
          fmt::format("  {:9.1f} {:8.2f} {:7.3f} {:7.3f}", row.range_m / 1e3, row.depression_deg,
                      r.model.contrast[i].g, r.truth.contrast[i].g);
      for (const ClarityDrawing& d : r.techniques)
        line += fmt::format(" {:12.3f}", d.contrast[i].g);
      out += line + "\n";
    }
    out += "  visibility (contrast 2 %), red / green / blue:\n";
    std::vector<const ClarityDrawing*> all = {&r.model, &r.truth};
    for (const ClarityDrawing& d : r.techniques) all.push_back(&d);
    for (const ClarityDrawing* d : all) {
      out += fmt::format("  {:>12}: {} / {} / {}\n", d->name, visibility_text(*d, 0),
                         visibility_text(*d, 1), visibility_text(*d, 2));
    }
  }
  return out;
}

std::string clarity_csv(const std::vector<ClarityResult>& results) {
  std::string out =
      "view,row,range_m,depression_deg,drawing,contrast_r,contrast_g,contrast_b,"
      "dark_r,dark_g,dark_b,bright_r,bright_g,bright_b,ground_dark_g,ground_bright_g\n";
  for (const ClarityResult& r : results) {
    std::vector<const ClarityDrawing*> all = {&r.model, &r.truth};
    for (const ClarityDrawing& d : r.techniques) all.push_back(&d);
    for (const ClarityRow& row : r.rows) {
      for (const ClarityDrawing* d : all) {
        size_t i = size_t(row.row);
        glm::dvec3 dark(0.0), bright(0.0);
        if (!d->dark.pixels.empty()) {
          dark = row_mean(d->dark, row.row);
          bright = row_mean(d->bright, row.row);
        }
        out += fmt::format(
            "{},{},{:.1f},{:.3f},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},"
            "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n",
            r.view.name, row.row, row.range_m, row.depression_deg, d->name, d->contrast[i].r,
            d->contrast[i].g, d->contrast[i].b, dark.r, dark.g, dark.b, bright.r, bright.g,
            bright.b, row.ground_dark.g, row.ground_bright.g);
      }
    }
  }
  return out;
}

}  // namespace planet
