#pragma once
// planet lab measured: the ground truth and each technique against a
// measured day (measured_comparison.h), per capture and in total, beside
// the figures Bruneton's 2016 evaluation published for the same
// measurements. Writes OUT/measured.json (every spectrum, every score),
// OUT/measured.csv (a row per source and capture) and keeps the ground
// truth's spectra in OUT/ground_truth/, so that a run that stops goes on.
#include "lab/measured_comparison.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace planet {

struct MeasuredOptions {
  std::filesystem::path data = "data/measured/kider-2013-05-27";
  std::string body = "earth_kider_2013";  // data/planets/<body>.json
  // Empty: every technique at its default; {"none"}: the ground truth alone.
  std::vector<std::string> techniques;
  std::vector<std::string> captures;      // local "HH:MM"; empty: every one
  int directions = 81;  // spread over the scan, the zenith always among them
  int paths = 4000;     // per direction and spectral sample
  // The scanner's azimuths as recorded; otherwise (the default) turned,
  // capture by capture, so that the sky's axis of symmetry falls on the
  // ephemeris's sun azimuth. The recorded axis lies 7-13 degrees west of
  // the sun in the shipped captures, by an amount that grows through the
  // morning (a drift of the scanner's heading, which Bruneton's 2016
  // evaluation corrected the same way).
  bool as_recorded = false;
  std::filesystem::path out = "out/lab/measured";
};

// The published total spectral RMSE (mW m^-2 sr^-1 nm^-1) of Bruneton's
// evaluation on the same day, by model, for the report's table.
struct PublishedRmse {
  const char* model;
  double rmse;
};
std::vector<PublishedRmse> published_rmse();

struct MeasuredRow {
  std::string source;   // "ground_truth" or a technique
  std::string capture;  // "09:30"
  MeasuredScore score;
};

// The captures and views, after checking every input (the folder, the
// body, the names): InputError before any long work.
struct MeasuredPlan {
  std::vector<MeasuredCapture> captures;
  std::vector<MeasuredView> views;
  std::vector<std::string> techniques;
};
MeasuredPlan plan_measured(const MeasuredOptions& options);

// Runs the plan; on_progress(label, done, total) for each stage. Needs a
// current GL context for the techniques.
std::vector<MeasuredRow> run_measured(const MeasuredOptions& options, const MeasuredPlan& plan,
                                      const std::function<void(const std::string&, int, int)>&
                                          on_progress = {});

// A readable table of the rows and the totals; also written to OUT.
std::string measured_summary(const MeasuredOptions& options, const MeasuredPlan& plan,
                             const std::vector<MeasuredRow>& rows);

}  // namespace planet
