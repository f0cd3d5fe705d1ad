#include "lab/gpu/measured_run.h"

#include "atmosphere/gpu/registry.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/job.h"
#include "lab/gpu/measured_render.h"
#include "sim/body.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace planet {

namespace {

// The directions kept: `n` spread evenly over the scan's order, the zenith
// (the last) always among them.
std::vector<size_t> kept_directions(size_t total, int n) {
  std::vector<size_t> out;
  size_t count = std::clamp<size_t>(size_t(n), 1, total);
  for (size_t k = 0; k < count; ++k) {
    out.push_back(count == 1 ? total - 1 : k * (total - 1) / (count - 1));
  }
  return out;
}

MeasuredCapture with_directions(MeasuredCapture c, const std::vector<size_t>& kept) {
  std::vector<MeasuredDirection> d;
  for (size_t i : kept) d.push_back(c.directions[i]);
  c.directions = std::move(d);
  return c;
}

// Root mean square over the captures of each one's RMSE (every capture has
// as many samples): Bruneton's total.
double total_rmse(const std::vector<MeasuredRow>& rows, const std::string& source, bool debiased) {
  double sum = 0;
  int n = 0;
  for (const MeasuredRow& r : rows) {
    if (r.source != source) continue;
    double v = debiased ? r.score.debiased_rmse : r.score.rmse;
    sum += v * v;
    ++n;
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

// The same over the directions away from the sun, pooled over the captures
// (they hold different numbers of such directions), and the share of the
// squared error within the aureole.
double total_away_rmse(const std::vector<MeasuredRow>& rows, const std::string& source,
                       double* near_sun_share) {
  double away = 0, all = 0;
  int n = 0;
  for (const MeasuredRow& r : rows) {
    if (r.source != source) continue;
    away += r.score.rmse_away_from_sun * r.score.rmse_away_from_sun * r.score.away_samples;
    all += r.score.rmse * r.score.rmse * r.score.samples;
    n += r.score.away_samples;
  }
  *near_sun_share = all > 0.0 ? 1.0 - away / all : 0.0;
  return n ? std::sqrt(away / n) : 0.0;
}

}  // namespace

std::vector<PublishedRmse> published_rmse() {
  return {{"Bruneton 2008 (3 wavelengths, 4 orders)", 11.3},
          {"Nishita 1996", 18.1},
          {"Nishita 1993", 26.5},
          {"Hosek-Wilkie", 41.6},
          {"O'Neil", 49.8},
          {"Preetham", 88.7}};
}

MeasuredPlan plan_measured(const MeasuredOptions& o) {
  if (o.paths < 16 || o.paths > 10000000) {
    throw InputError(fmt::format("--paths: {} is not within 16 to 10000000", o.paths));
  }
  if (o.directions < 1 || o.directions > 81) {
    throw InputError(fmt::format("--directions: {} is not within 1 to 81", o.directions));
  }
  MeasuredPlan plan;
  // "none": the ground truth alone.
  bool none = o.techniques.size() == 1 && o.techniques[0] == "none";
  if (!none) {
    for (const std::string& t : o.techniques) parse_technique(t);  // names checked now
    plan.techniques = o.techniques;
    if (plan.techniques.empty()) plan.techniques = technique_names();
  }

  std::vector<MeasuredCapture> all = load_measured_day(o.data);
  for (const std::string& wanted : o.captures) {
    bool found = std::any_of(all.begin(), all.end(),
                             [&](const MeasuredCapture& c) { return c.local == wanted; });
    if (!found) {
      std::string known;
      for (const MeasuredCapture& c : all) known += (known.empty() ? "" : ", ") + c.local;
      throw InputError(fmt::format("--captures: {} is not a capture of {} ({})", wanted,
                                   o.data.string(), known));
    }
  }
  MeasuredSite site;
  for (MeasuredCapture& c : all) {
    if (!o.captures.empty() &&
        std::find(o.captures.begin(), o.captures.end(), c.local) == o.captures.end()) {
      continue;
    }
    MeasuredCapture kept = with_directions(c, kept_directions(c.directions.size(), o.directions));
    MeasuredView view = measured_view(kept, o.body, site);
    double symmetry = symmetry_azimuth_deg(c, view.sun_azimuth_deg);
    if (!o.as_recorded) {
      double turn = view.sun_azimuth_deg - symmetry;
      for (MeasuredDirection& d : kept.directions) {
        d.azimuth_deg = std::fmod(d.azimuth_deg + turn + 360.0, 360.0);
      }
      view = measured_view(kept, o.body, site);
      view.azimuth_turn_deg = turn;
    }
    view.symmetry_azimuth_deg = symmetry;
    Body body = scene_body(view.scene);
    if (!scene_atmosphere(view.scene, body).spectrum) {
      throw InputError(fmt::format("{}: the atmosphere has no spectrum to compare with a measured "
                                   "one (give it \"inputs\" or a \"spectrum\")",
                                   body.file.string()));
    }
    plan.captures.push_back(std::move(kept));
    plan.views.push_back(std::move(view));
  }
  return plan;
}

namespace {

using MeasuredProgress = std::function<void(const std::string&, int, int)>;

// The ground truth as a job, a cell per capture (measured_comparison.h's
// ground_truth_cell), kept in OUT/ground_truth as each one ends.
std::vector<SkySpectra> ground_truths(const MeasuredOptions& o, const MeasuredPlan& plan,
                                      const AtmosphereModel& model,
                                      const MeasuredProgress& on_progress) {
  std::vector<JobCell> cells;
  std::vector<GroundTruthCell> keys;
  for (size_t c = 0; c < plan.captures.size(); ++c) {
    keys.push_back(ground_truth_cell(model, plan.views[c], plan.captures[c], o.paths));
    cells.push_back({keys.back().file, plan.captures[c].local, "", c});
  }
  const int directions = int(plan.captures.front().directions.size());
  const int total = directions * int(plan.captures.size());
  std::vector<SkySpectra> truth(plan.captures.size());
  JobSteps steps;
  steps.keep = [&](const JobCell& cell, const std::filesystem::path& file) {
    std::optional<SkySpectra> kept = read_ground_truth(file, keys[cell.index].key);
    if (!kept) return false;
    truth[cell.index] = *kept;
    if (on_progress) on_progress("ground truth", int(cell.index + 1) * directions, total);
    return true;
  };
  steps.run = [&](const JobCell& cell) {
    const size_t c = cell.index;
    truth[c] = ground_truth_spectra(model, plan.views[c], o.paths, [&](int done) {
      if (on_progress) on_progress("ground truth", int(c) * directions + done, total);
    });
    return ground_truth_json(keys[c], plan.captures[c], o.paths, model.spectrum->wavelengths_nm,
                             truth[c]);
  };
  Job(o.out / "ground_truth", cells).run(steps);
  return truth;
}

nlohmann::json score_json(const MeasuredScore& s) {
  return nlohmann::json{{"rmse", s.rmse},
                        {"debiased_rmse", s.debiased_rmse},
                        {"zenith_luminance", s.zenith_luminance},
                        {"measured_zenith_luminance", s.measured_zenith_luminance},
                        {"mean_measured", s.mean_measured},
                        {"rmse_away_from_sun", s.rmse_away_from_sun},
                        {"near_sun_share", s.near_sun_share}};
}

// A capture's entry in measured.json: its sun, directions, measurements,
// and each source's radiance and score.
nlohmann::json capture_json(const MeasuredCapture& cap, const MeasuredView& view,
                            const std::vector<double>& wavelengths, const SkySpectra& truth,
                            const std::map<std::string, SkySpectra>& by_technique,
                            const std::vector<MeasuredRow>& rows) {
  nlohmann::json j;
  j["local"] = cap.local;
  j["utc"] = cap.utc;
  j["sun"] = {{"elevation_deg", view.sun_elevation_deg},
              {"azimuth_deg", view.sun_azimuth_deg},
              {"symmetry_azimuth_deg", view.symmetry_azimuth_deg},
              {"azimuth_turn_deg", view.azimuth_turn_deg}};
  nlohmann::json dirs = nlohmann::json::array(), measured = nlohmann::json::array();
  for (const MeasuredDirection& d : cap.directions) {
    dirs.push_back(
        {{"index", d.index}, {"azimuth_deg", d.azimuth_deg}, {"elevation_deg", d.elevation_deg}});
    std::vector<double> bands;
    for (double l : wavelengths) bands.push_back(cap.band_radiance(d, l));
    measured.push_back(bands);
  }
  j["directions"] = dirs;
  j["measured"] = measured;
  j["sources"]["ground_truth"] = {{"radiance", truth.radiance}, {"std_error", truth.std_error}};
  for (const auto& [t, spectra] : by_technique) j["sources"][t] = {{"radiance", spectra.radiance}};
  for (const MeasuredRow& r : rows) {
    if (r.capture == cap.local) j["sources"][r.source]["score"] = score_json(r.score);
  }
  return j;
}

void write_measured_tables(const MeasuredOptions& o, const MeasuredPlan& plan,
                           const std::vector<double>& wavelengths,
                           const std::vector<SkySpectra>& truth,
                           const std::map<std::string, std::vector<SkySpectra>>& by_technique,
                           const std::vector<MeasuredRow>& rows) {
  nlohmann::json captures = nlohmann::json::array();
  for (size_t c = 0; c < plan.captures.size(); ++c) {
    std::map<std::string, SkySpectra> techniques;
    for (const auto& [t, spectra] : by_technique) techniques[t] = spectra[c];
    captures.push_back(
        capture_json(plan.captures[c], plan.views[c], wavelengths, truth[c], techniques, rows));
  }
  nlohmann::json totals;
  std::vector<std::string> sources = {"ground_truth"};
  sources.insert(sources.end(), plan.techniques.begin(), plan.techniques.end());
  for (const std::string& s : sources) {
    double share = 0;
    double away = total_away_rmse(rows, s, &share);
    totals[s] = {{"rmse", total_rmse(rows, s, false)},
                 {"debiased_rmse", total_rmse(rows, s, true)},
                 {"rmse_away_from_sun", away},
                 {"near_sun_share", share}};
  }
  nlohmann::json published = nlohmann::json::array();
  for (const PublishedRmse& p : published_rmse()) {
    published.push_back({{"model", p.model}, {"rmse", p.rmse}});
  }
  nlohmann::json doc = {{"data", o.data.string()},
                        {"body", o.body},
                        {"paths", o.paths},
                        {"wavelengths_nm", wavelengths},
                        {"compare_nm", {kCompareFirstNm, kCompareLastNm}},
                        {"unit", "radiance W m^-2 sr^-1 nm^-1; rmse mW m^-2 sr^-1 nm^-1; "
                                 "luminance cd/m^2"},
                        {"captures", captures},
                        {"totals", totals},
                        {"published", published}};
  write_file_atomically(o.out / "measured.json", doc.dump(1));

  std::string csv =
      "source,capture,rmse,debiased_rmse,zenith_luminance,measured_zenith_luminance,"
      "rmse_away_from_sun,near_sun_share\n";
  for (const MeasuredRow& r : rows) {
    csv += fmt::format("{},{},{:.3f},{:.3f},{:.1f},{:.1f},{:.3f},{:.3f}\n", r.source, r.capture,
                       r.score.rmse, r.score.debiased_rmse, r.score.zenith_luminance,
                       r.score.measured_zenith_luminance, r.score.rmse_away_from_sun,
                       r.score.near_sun_share);
  }
  write_file_atomically(o.out / "measured.csv", csv);
}

}  // namespace

std::vector<MeasuredRow> run_measured(const MeasuredOptions& o, const MeasuredPlan& plan,
                                      const MeasuredProgress& on_progress) {
  Body body = scene_body(plan.views.front().scene);
  AtmosphereModel model = scene_atmosphere(plan.views.front().scene, body);
  const std::vector<double>& wavelengths = model.spectrum->wavelengths_nm;
  auto score = [&](size_t c, const SkySpectra& spectra) {
    return score_against(plan.captures[c], spectra, wavelengths, plan.views[c].sun_elevation_deg,
                         plan.views[c].sun_azimuth_deg);
  };
  std::vector<MeasuredRow> rows;
  std::vector<SkySpectra> truth = ground_truths(o, plan, model, on_progress);
  for (size_t c = 0; c < plan.captures.size(); ++c) {
    rows.push_back({"ground_truth", plan.captures[c].local, score(c, truth[c])});
  }
  std::map<std::string, std::vector<SkySpectra>> by_technique;
  for (const std::string& t : plan.techniques) {
    by_technique[t] = technique_spectra(t, plan.views, [&](int done, int triples) {
      if (on_progress) on_progress(t, done, triples);
    });
    for (size_t c = 0; c < plan.captures.size(); ++c) {
      rows.push_back({t, plan.captures[c].local, score(c, by_technique[t][c])});
    }
  }
  write_measured_tables(o, plan, wavelengths, truth, by_technique, rows);
  return rows;
}

std::string measured_summary(const MeasuredOptions& o, const MeasuredPlan& plan,
                             const std::vector<MeasuredRow>& rows) {
  std::vector<std::string> sources = {"ground_truth"};
  sources.insert(sources.end(), plan.techniques.begin(), plan.techniques.end());
  std::string out = fmt::format(
      "Spectral RMSE against the measurements ({}-{} nm, {} directions; mW m^-2 sr^-1 nm^-1; the "
      "ground truth's noise taken out) and zenith luminance (cd/m^2, modelled / measured):\n",
      kCompareFirstNm, kCompareLastNm, plan.captures.front().directions.size());
  out += fmt::format("{:<22}", "source");
  for (const MeasuredCapture& c : plan.captures) out += fmt::format("{:>16}", c.local);
  out += fmt::format("{:>9}\n", "total");
  for (const std::string& s : sources) {
    out += fmt::format("{:<22}", s);
    for (const MeasuredCapture& c : plan.captures) {
      for (const MeasuredRow& r : rows) {
        if (r.source != s || r.capture != c.local) continue;
        out += fmt::format("{:>6.1f} {:>4.0f}/{:<4.0f}", r.score.debiased_rmse,
                           r.score.zenith_luminance, r.score.measured_zenith_luminance);
      }
    }
    out += fmt::format("{:>9.1f}\n", total_rmse(rows, s, true));
  }
  out += fmt::format("In total, beyond {:g} deg of the sun (and the share of the squared error "
                     "within it):",
                     kAureoleDeg);
  for (const std::string& s : sources) {
    double share = 0;
    double away = total_away_rmse(rows, s, &share);
    out += fmt::format(" {} {:.1f} ({:.0f} %);", s, away, 100.0 * share);
  }
  out += "\n";
  out += "Published on the same day (Bruneton 2016, total):";
  for (const PublishedRmse& p : published_rmse()) out += fmt::format(" {} {};", p.model, p.rmse);
  out += fmt::format("\nSun: our ephemeris against the sky's axis of symmetry (azimuth, deg; the "
                     "scan's azimuths {}):",
                     o.as_recorded ? "as recorded" : "turned to agree");
  for (size_t c = 0; c < plan.views.size(); ++c) {
    out += fmt::format(" {} {:.1f}/{:.1f};", plan.captures[c].local, plan.views[c].sun_azimuth_deg,
                       plan.views[c].symmetry_azimuth_deg);
  }
  out += "\n";
  write_file_atomically(o.out / "summary.txt", out);
  return out;
}

}  // namespace planet
