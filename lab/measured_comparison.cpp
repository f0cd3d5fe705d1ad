#include "lab/measured_comparison.h"

#include "atmosphere/reference/columns.h"
#include "atmosphere/reference/medium.h"
#include "atmosphere/reference/path_tracer.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/parallel.h"
#include "lab/reference_cache.h"
#include "sim/body.h"
#include "sim/geodesy.h"
#include "sim/sun_ephemeris.h"
#include "sim/utc_time.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <fstream>

namespace planet {

namespace {

// The faces measured_render.h draws are this many pixels a side.
constexpr int kFacePixels = 96;

glm::dvec3 enu(double azimuth_deg, double elevation_deg) {
  double az = glm::radians(azimuth_deg), el = glm::radians(elevation_deg);
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

// 16 hex digits of (model, camera, sun, directions, paths, the tracer's version).
std::string spectra_key(const AtmosphereModel& model, const MeasuredView& view, int paths) {
  Fnv1a h;
  std::string model_key = reference_model_key(model, ReferenceMode::kSpectral);
  h.bytes(model_key.data(), model_key.size());
  auto vec = [&](const glm::dvec3& v) { h.bytes(&v, sizeof v); };
  vec(view.camera_atmo), vec(view.sun_dir_atmo);
  for (const glm::dvec3& d : view.directions_atmo) vec(d);
  double numbers[2] = {double(paths), double(kReferenceVersion)};
  h.bytes(numbers, sizeof numbers);
  return fmt::format("{:016x}", h.value());
}

}  // namespace

MeasuredView measured_view(const MeasuredCapture& capture, const std::string& body_name,
                           const MeasuredSite& site) {
  MeasuredView v;
  Scene base;
  base.name = "measured-" + capture.date + "-" + capture.local;
  base.description = "the measured sky of " + capture.date + " " + capture.local + " local";
  base.body = body_name;
  base.width = base.height = kFacePixels;
  base.exposure = 10.0;
  ScenePlacement up;
  up.lat_deg = site.lat_deg;
  up.lon_deg = site.lon_deg;
  up.height_m = 2.0;
  up.pitch_deg = 90.0;
  up.vertical_fov_deg = 90.0;
  v.scene = placed(base, up);
  v.placement = up;

  Body body = scene_body(v.scene);
  if (!body.ephemeris.available()) {
    throw InputError(fmt::format("{}: {} has no \"ephemeris\" to place the sun of {}",
                                 body.file.string(), body.name, capture.utc));
  }
  UtcSeconds utc = parse_utc(capture.utc, capture.dir.string());
  v.scene.sun_dir_body = sun_dir_body(body.ephemeris, body.rotation, utc);
  HorizonAngles a = horizon_angles(v.scene.sun_dir_body, glm::radians(site.lat_deg),
                                   glm::radians(site.lon_deg));
  v.sun_elevation_deg = glm::degrees(a.elevation);
  v.sun_azimuth_deg = glm::degrees(a.azimuth);

  AtmosphereModel model = scene_atmosphere(v.scene, body);
  ReferenceView rv = reference_view(v.scene, body, model);
  v.camera_atmo = rv.camera_atmo;
  v.sun_dir_atmo = rv.sun_dir_atmo;
  for (const MeasuredDirection& d : capture.directions) {
    v.directions_atmo.push_back(glm::normalize(rv.frame * enu(d.azimuth_deg, d.elevation_deg)));
  }
  return v;
}

SkySpectra ground_truth_spectra(const AtmosphereModel& model, const MeasuredView& view, int paths,
                                const std::function<void(int)>& on_progress) {
  Medium medium = make_medium(model, ReferenceMode::kSpectral);
  const ColumnTable table(medium);
  size_t channels = medium.channels.size();
  int count = int(view.directions_atmo.size());
  SkySpectra out;
  out.radiance.assign(size_t(count), std::vector<double>(channels, 0.0));
  out.std_error = out.radiance;
  TraceOptions options;
  parallel_for(
      count, 0,
      [&](int i) {
        for (size_t c = 0; c < channels; ++c) {
          uint64_t seed = 0x6b1de5ull * 1000003ull + uint64_t(i) * 131ull + c;
          RadianceEstimate e = estimate_radiance(table, c, view.camera_atmo,
                                                 view.directions_atmo[size_t(i)], view.sun_dir_atmo,
                                                 options, paths, seed);
          out.radiance[size_t(i)][c] = e.mean;
          out.std_error[size_t(i)][c] = e.std_error;
        }
      },
      on_progress);
  return out;
}

GroundTruthCell ground_truth_cell(const AtmosphereModel& model, const MeasuredView& view,
                                  const MeasuredCapture& capture, int paths) {
  std::string key = spectra_key(model, view, paths);
  return {fmt::format("{}_{}-{}paths-{}.json", capture.date,
                      capture.local.substr(0, 2) + capture.local.substr(3, 2), paths, key),
          key};
}

std::string ground_truth_json(const GroundTruthCell& cell, const MeasuredCapture& capture,
                              int paths, const std::vector<double>& wavelengths_nm,
                              const SkySpectra& s) {
  nlohmann::json j = {{"key", cell.key},        {"capture", capture.date + " " + capture.local},
                      {"paths", paths},         {"wavelengths_nm", wavelengths_nm},
                      {"radiance", s.radiance}, {"std_error", s.std_error}};
  return j.dump();
}

std::optional<SkySpectra> read_ground_truth(const std::filesystem::path& file,
                                            const std::string& key) {
  std::ifstream in(file);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || j.value("key", "") != key) return std::nullopt;
  SkySpectra s;
  s.radiance = j.at("radiance").get<std::vector<std::vector<double>>>();
  s.std_error = j.at("std_error").get<std::vector<std::vector<double>>>();
  return s;
}

std::vector<double> spectrum_every_nm(const std::vector<double>& samples,
                                      const std::vector<double>& wavelengths_nm) {
  std::vector<double> out;
  size_t k = 0;
  for (int nm = 360; nm <= 830; ++nm) {
    double l = double(nm);
    while (k + 1 < wavelengths_nm.size() && wavelengths_nm[k + 1] < l) ++k;
    if (l <= wavelengths_nm.front()) {
      out.push_back(samples.front());
    } else if (l >= wavelengths_nm.back()) {
      out.push_back(samples.back());
    } else {
      double f = (l - wavelengths_nm[k]) / (wavelengths_nm[k + 1] - wavelengths_nm[k]);
      out.push_back(samples[k] * (1.0 - f) + samples[k + 1] * f);
    }
  }
  return out;
}

MeasuredScore score_against(const MeasuredCapture& capture, const SkySpectra& spectra,
                            const std::vector<double>& wavelengths_nm, double sun_elevation_deg,
                            double sun_azimuth_deg) {
  MeasuredScore s;
  double squares = 0, noise = 0, measured = 0, away = 0;
  int count = 0, away_count = 0;
  glm::dvec3 sun = enu(sun_azimuth_deg, sun_elevation_deg);
  double cos_aureole = std::cos(glm::radians(kAureoleDeg));
  for (size_t i = 0; i < capture.directions.size(); ++i) {
    const MeasuredDirection& dir = capture.directions[i];
    bool near_sun = glm::dot(enu(dir.azimuth_deg, dir.elevation_deg), sun) > cos_aureole;
    for (size_t k = 0; k < wavelengths_nm.size(); ++k) {
      double l = wavelengths_nm[k];
      if (l < kCompareFirstNm || l > kCompareLastNm) continue;
      double m = capture.band_radiance(capture.directions[i], l);
      double d = spectra.radiance[i][k] - m;
      squares += d * d;
      if (!near_sun) away += d * d, ++away_count;
      if (!spectra.std_error.empty()) noise += spectra.std_error[i][k] * spectra.std_error[i][k];
      measured += m;
      ++count;
    }
  }
  s.rmse = 1e3 * std::sqrt(squares / count);
  s.debiased_rmse = 1e3 * std::sqrt(std::max(squares - noise, 0.0) / count);
  s.mean_measured = 1e3 * measured / count;
  s.samples = count;
  s.away_samples = away_count;
  s.rmse_away_from_sun = away_count ? 1e3 * std::sqrt(away / away_count) : 0.0;
  s.near_sun_share = squares > 0.0 ? 1.0 - away / squares : 0.0;
  s.zenith_luminance =
      luminance_cd_m2(spectrum_every_nm(spectra.radiance.back(), wavelengths_nm), 360);
  s.measured_zenith_luminance = luminance_cd_m2(capture.zenith().radiance, capture.first_nm);
  return s;
}

}  // namespace planet
