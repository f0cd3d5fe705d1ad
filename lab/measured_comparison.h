#pragma once
// A sky model against a measured sky (measured_sky.h): the ground truth's
// and each technique's spectral radiance in the measured directions, and
// the scores of Bruneton's 2016 evaluation of clear-sky models against the
// same measurements: the spectral RMSE over every direction and every
// spectral sample from 360 to 720 nm, in mW m^-2 sr^-1 nm^-1, and the
// zenith luminance in cd/m^2.
//
// Every source answers at the model's spectral samples (a derived
// atmosphere's: 360-830 nm every 10 nm, atmosphere_inputs.h); the
// measurement is averaged over each sample's 10 nm bin.
#include "atmosphere/model.h"
#include "lab/measured_sky.h"
#include "lab/scene.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace planet {

// The spectral samples the RMSE sums over: 360 to 720 nm.
constexpr double kCompareFirstNm = 360.0, kCompareLastNm = 720.0;

// What one source gives for one capture: radiance[direction][sample],
// W m^-2 sr^-1 nm^-1 at the model's spectral samples, and, for the ground
// truth, each value's standard error (empty for a technique).
struct SkySpectra {
  std::vector<std::vector<double>> radiance, std_error;
};

struct MeasuredScore {
  double rmse = 0;           // mW m^-2 sr^-1 nm^-1, noise included
  double debiased_rmse = 0;  // the ground truth's noise taken out (= rmse for a technique)
  double zenith_luminance = 0, measured_zenith_luminance = 0;  // cd/m^2
  double mean_measured = 0;  // the measurement's mean over the same samples, mW m^-2 sr^-1 nm^-1
  // The same RMSE (noise included) over the directions at least
  // kAureoleDeg from the sun, and the share of the squared error that the
  // directions nearer it carry: where a phase function's forward peak
  // shows.
  double rmse_away_from_sun = 0, near_sun_share = 0;
  int samples = 0, away_samples = 0;  // what each RMSE averages over
};

// The aureole's radius for MeasuredScore, degrees.
constexpr double kAureoleDeg = 10.0;

// A capture as the frame and the ground truth see it: the scene of the
// camera 2 m above the site, looking up, with the sun where our ephemeris
// puts it at the capture's UTC, and the measured directions and sun in
// atmosphere space.
struct MeasuredView {
  Scene scene;  // the upward face (measured_render.h draws five faces around it)
  ScenePlacement placement;  // the upward face's
  double sun_elevation_deg = 0, sun_azimuth_deg = 0;  // from the ephemeris
  // The sun's azimuth as the measured sky gives it (symmetry_azimuth_deg
  // on the whole scan), and the turn given to the scan's azimuths so that
  // the two agree (0 where the scan is taken as recorded).
  double symmetry_azimuth_deg = 0, azimuth_turn_deg = 0;
  glm::dvec3 camera_atmo{0.0}, sun_dir_atmo{0.0};
  std::vector<glm::dvec3> directions_atmo;  // unit, one per measured direction
};

// `body_name` names the body preset (a file or data/planets name) whose
// atmosphere models the day.
MeasuredView measured_view(const MeasuredCapture& capture, const std::string& body_name,
                           const MeasuredSite& site);

// The ground truth (the path tracer, spectral, every order) in each
// direction at each spectral sample, `paths` paths each; on_progress(done)
// counts directions. Bits independent of the thread count.
SkySpectra ground_truth_spectra(const AtmosphereModel& model, const MeasuredView& view, int paths,
                                const std::function<void(int)>& on_progress = {});

// A capture's ground truth as a cell of a job (core/job.h): its file's
// name, "<date>_<HHMM>-<paths>paths-<key>.json", under a key of (model,
// view, paths), so that a lab run that stops goes on from the captures it
// finished, and a changed model or view is traced again.
struct GroundTruthCell {
  std::string file, key;
};
GroundTruthCell ground_truth_cell(const AtmosphereModel& model, const MeasuredView& view,
                                  const MeasuredCapture& capture, int paths);
// The cell's bytes, and the spectra read back from them (none where the
// file is not whole or is of another key).
std::string ground_truth_json(const GroundTruthCell& cell, const MeasuredCapture& capture,
                              int paths, const std::vector<double>& wavelengths_nm,
                              const SkySpectra& spectra);
std::optional<SkySpectra> read_ground_truth(const std::filesystem::path& file,
                                            const std::string& key);

// `sun_elevation_deg` and `sun_azimuth_deg` place the sun among the
// capture's directions.
MeasuredScore score_against(const MeasuredCapture& capture, const SkySpectra& spectra,
                            const std::vector<double>& wavelengths_nm, double sun_elevation_deg,
                            double sun_azimuth_deg);

// A spectrum at the model's samples, linearly interpolated to every nm
// over 360-830 (held beyond its ends), for luminance_cd_m2.
std::vector<double> spectrum_every_nm(const std::vector<double>& samples,
                                      const std::vector<double>& wavelengths_nm);

}  // namespace planet
