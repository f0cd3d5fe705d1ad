#pragma once
// Headless capture of a scripted flight: frame i at t = start + i / rate,
// each written as linear EXR, tone-mapped PNG and a JSON sidecar. The run
// is reproducible: the same script gives the same bytes on the same
// machine. capture.json, written last, marks a finished capture; it is
// removed first, so a capture that stops half-way never looks finished.
#include "atmosphere/gpu/registry.h"
#include "core/share.h"
#include "gl/pass_tally.h"
#include "governor/governor.h"
#include "render/capture_folder.h"
#include "render/capture_overrides.h"
#include "sim/flight_script.h"

#include <filesystem>
#include <optional>
#include <functional>
#include <stdexcept>

namespace planet {

struct CaptureOptions {
  std::filesystem::path out_dir;
  int first_frame = 0;
  int end_frame = -1;  // one past the last; -1 means the flight's end
  bool progress = true;
  double pixel_budget = 1.0;  // terrain: largest projected geometric error, pixels
  size_t terrain_cache_bytes = size_t(256) << 20;
  // Which share of a capture split over a cluster this run is
  // (capture_shares.h); capture.json records it for the merge.
  Share share;
  // --error-budget: the governor chooses each frame's technique (unless the
  // script names one, which wins), from this table (empty: the shipped one).
  std::optional<double> error_budget_percent;
  std::filesystem::path error_model_file;
  // Frames a switch fades over: 0 from the frame rate (a second, at least
  // 4); 1 switches at once (a pop, for the tests that must see one).
  int switch_fade_frames = 0;
  // What the command line put in place of the script's own, already in the
  // script the capture is given: recorded in every sidecar and capture.json.
  CaptureOverrides overrides;
  // --pass-table: each pass's wall time kept too (a synchronous timer), for
  // CaptureResult::passes.
  bool pass_table = false;
};

// The budget a capture of `script` runs the governor with: the command
// line's, else the script's; none where the script names its technique.
std::optional<double> capture_error_budget(const FlightScript& script,
                                           const CaptureOptions& options);

struct CaptureResult {
  int frames = 0;  // this run's
  double wall_seconds = 0;
  std::filesystem::path first_png, last_png;
  // The frames the folder holds whole after this run, with those earlier
  // runs left (capture.json's), and an earlier, longer capture's removed.
  FolderFrames folder;
  FramesBeyond removed;
  // This run's frames, pass by pass.
  PassTally passes;
};

// Ctrl-C during a capture: the frame in progress is finished and written,
// then this is thrown with the frames done and the --frames to resume with.
class CaptureInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The script's atmosphere technique and quality, checked against the
// registry without GL: InputError naming the script.
TechniqueChoice script_technique(const FlightScript& script);

// InputError unless the options' frames are a non-empty slice of the
// flight's.
void check_frames(const FlightScript& script, const CaptureOptions& options);

// Every keyframe above the ground under it (`ground`, terrain_ground() of
// terrain/ground.h), unless the script allows otherwise: InputError naming
// the keyframe, its height and the ground's. No GL needed.
void check_keyframes_above_ground(const FlightScript& script, const GroundHeight& ground);

// What identifies the flight a capture renders: a hash of its script's
// text, 16 hex digits. A share's capture.json holds it, with the
// program's version.
std::string flight_script_hash(const FlightScript& script);

// A capture's inputs, checked once before GL starts, and what they give:
// the slice of frames (check_frames), the script's technique
// (script_technique) and, where the governor chooses, its budget and its
// table, read here once. InputError for any of them.
struct CapturePlan {
  int first = 0, end = 0, total = 0;      // the slice [first, end) of the flight's total
  std::optional<double> budget;           // capture_error_budget
  std::optional<ErrorModel> error_model;  // with a budget
};
CapturePlan plan_capture(const FlightScript& script, const CaptureOptions& options);

// Needs a current GL context. Each frame's sidecar JSON is written after its
// images, so a frame with a sidecar is complete.
CaptureResult run_capture(const FlightScript& script, const CaptureOptions& options,
                          const CapturePlan& plan);
// The same, planned here.
CaptureResult run_capture(const FlightScript& script, const CaptureOptions& options);

}  // namespace planet
