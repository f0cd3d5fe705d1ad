#pragma once
// The governor: each frame, the technique and quality with the lowest
// predicted cost whose predicted error is within the user's budget, from
// the error-and-cost table the lab writes (data/lab/error_model.json, made
// by `planet lab run` from its measured cells). Nothing here renders or
// links the path tracer: the table is all it knows.
//
// A view is described by what the lab's errors depend on: the body, the
// camera's height against the shell's thickness, the sun's elevation at the
// point below the camera, the air's vertical optical depth and its Mie
// asymmetry, and the body's size. The table's rows are the lab's canonical
// scenes described the same way; a view is predicted from the rows nearest
// to it (another body's a little further off than its own), and where it
// is not one of them, from the worst of those near it, more of them the
// further it is (a view between measured ones is assumed as bad as the
// worst).
#include "atmosphere/model.h"
#include "sim/body.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace planet {

// What a view's errors depend on, as the governor sees it.
struct ViewFeatures {
  std::string body;                // the body's name (variants keep it)
  double altitude_m = 0;           // above the bottom sphere, in atmosphere space
  double shell_m = 1;              // the shell's thickness (top - bottom radius)
  double sun_elevation_deg = 0;    // above the horizon at the point below the camera
  double optical_depth = 0;        // vertical, bottom to top, at the green wavelength
  double mie_g = 0;
  double bottom_radius_m = 1;
};

// The view of a camera at `camera_pos_body` with the sun along
// `sun_dir_body`, on `body` under `model`.
ViewFeatures view_features(const Body& body, const AtmosphereModel& model,
                           const glm::dvec3& camera_pos_body, const glm::dvec3& sun_dir_body);

// How far apart two views are, in the units the governor weighs them by
// (about 1: a different view class): 0.15 of a decade of (1 + altitude in
// shell thicknesses), so that from inside the shell to 400 km above Earth's
// is nearly 5, 10 degrees of sun, a factor of 3 in optical depth, 0.1 in g,
// a decade of radius. Infinite between two bodies.
double view_distance(const ViewFeatures& a, const ViewFeatures& b);

// One (technique, quality) measured on one of the lab's views.
struct ErrorModelEntry {
  std::string choice;       // the registry's text: "hillaire:cheap" as parse_technique reads it
  double error = 0;         // worst channel's relative RMSE against the ground truth, its noise out
  double error_high = 0;    // the top of its 95 % interval
  double frame_ms = 0;      // the atmosphere's passes per frame, model unchanged, at time_size
};

struct ViewClass {
  std::string scene;        // the lab's canonical scene it was measured on
  ViewFeatures view;
  std::vector<ErrorModelEntry> entries;
};

struct ErrorModel {
  std::string source;       // what made it: the program's version, commit, renderer
  int time_width = 0, time_height = 0;
  // What a change of model recomputes, per choice, ms (the technique's
  // tables from nothing, no disk cache): a switch to it, or a slider moved
  // while it draws, costs this once.
  std::map<std::string, double> model_change_ms;
  std::vector<ViewClass> classes;
};

// InputError naming the file (or `where`) and the field for anything this
// program did not write or cannot use.
ErrorModel parse_error_model(const nlohmann::json& json, const std::string& where);
ErrorModel load_error_model(const std::filesystem::path& file);
nlohmann::json error_model_to_json(const ErrorModel& model);
// data/lab/error_model.json, the shipped table.
std::filesystem::path shipped_error_model_file();

// A budget given on the command line or in a script: InputError unless it
// is a percentage above 0 and at most 1000.
double checked_error_budget(double percent, const std::string& where);

// What the table predicts for one choice at a view.
struct Prediction {
  std::string choice;
  double error = 0;         // fraction
  double frame_ms = 0;      // per frame, model unchanged
  double cost_ms = 0;       // frame_ms, plus the model change spread over frames_per_model
                            // where its tables are not built yet
};

struct GovernorSettings {
  double budget_percent = 5.0;
  // A model change's cost is spread over this many frames (a capture sets
  // its own frame count; a window the frames it expects to draw before the
  // model changes); 0: the frame's cost alone, as the lab's table has it.
  double frames_per_model = 600;
  // Hysteresis: a cheaper choice is taken only when it saves at least this
  // share of the cost and has been the cheapest this many frames in a row;
  // a choice over budget is left at once.
  double switch_gain = 0.15;
  int dwell_frames = 15;
  // A switch fades from the old technique's frame to the new one's over
  // this many frames (smoothstep), so that it does not pop.
  int fade_frames = 24;
};

struct GovernorDecision {
  bool governed = false;    // false: nothing in the table for this body; `choice` is the fallback
  std::string choice;       // what this frame draws
  Prediction chosen;        // its prediction
  Prediction cheapest;      // the cheapest within budget now (differs from chosen while hysteresis holds)
  Prediction most_accurate; // the lowest predicted error: what the frame would cost otherwise
  std::vector<std::string> classes;  // the lab's scenes the prediction came from
  double distance = 0;      // to the nearest of them (view_distance)
  bool within_budget = false;
  std::string why;          // one line a person reads
  // While a switch fades: the choice before it and its share of the frame.
  std::string fading_from;
  double fade_weight = 0;

  nlohmann::json to_json(double budget_percent) const;
};

class Governor {
 public:
  // `fallback`: what draws where the table has no row for the body.
  Governor(ErrorModel model, GovernorSettings settings, std::string fallback);

  // The choice for this frame's view; call once per frame, in order (the
  // hysteresis and the fade count frames).
  GovernorDecision decide(const ViewFeatures& view);
  // Every choice's prediction at a view, cheapest first; none for a body
  // the table does not have.
  std::vector<Prediction> predict(const ViewFeatures& view, std::vector<std::string>* classes = nullptr,
                                  double* distance = nullptr) const;

  void set_budget(double percent) { settings_.budget_percent = percent; }
  // The model changed: every choice's tables are to be built again.
  void model_changed() { built_.clear(); }
  const GovernorSettings& settings() const { return settings_; }
  const ErrorModel& model() const { return model_; }

 private:
  ErrorModel model_;
  GovernorSettings settings_;
  std::string fallback_;
  std::string current_;
  std::string candidate_;
  int candidate_frames_ = 0;
  std::string fading_from_;
  int fade_frame_ = 0;
  // The choices drawn since the model last changed: their tables are built
  // (TechniqueSwitch keeps them), so a switch back costs no model change.
  std::set<std::string> built_;
};

}  // namespace planet
