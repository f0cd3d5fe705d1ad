#pragma once
// planet lab clarity: each clarity view (lab/clarity.h) over both grounds,
// drawn by the ground truth (cached like every reference) and by each
// technique through the frame, and its contrast against distance.
#include "core/image_io.h"
#include "lab/clarity.h"

#include <functional>
#include <string>
#include <vector>

namespace planet {

struct ClarityOptions {
  std::vector<std::string> views;       // default: every clarity view
  std::vector<std::string> techniques;  // default: every technique, at its default quality
  PathBudget paths = clarity_reference_paths();
  int ground_paths = 2048;  // per row and channel, for the targets' own radiance
  bool uniform = false;     // two uniform grounds, not two targets (lab/clarity.h)
};

// One drawing of a view over both grounds, and its contrast per row.
struct ClarityDrawing {
  std::string name;  // "truth" or the technique's name
  ImageRGB dark, bright;
  std::vector<glm::dvec3> contrast;  // per row; 0 off the ground
  glm::dvec3 visibility_m{0.0};      // per channel; negative: beyond the horizon
  glm::dvec3 at_horizon{0.0};        // the contrast at the last ground row
};

struct ClarityResult {
  Scene view;
  std::vector<ClarityRow> rows;
  ClarityDrawing model;  // exp(-tau) as the contrast: the model's transmittance
  ClarityDrawing truth;
  std::vector<ClarityDrawing> techniques;
  glm::dvec3 koschmieder_eye_m{0.0}, koschmieder_ground_m{0.0};
  bool uniform = false;
  double ground_albedo = 0;  // the model's (green), around the targets
};

// Every view asked for, checked before any work; InputError otherwise.
std::vector<Scene> clarity_plan(const ClarityOptions& options);
// `truth` gives a scene's ground truth (the command's: from the reference
// cache, where data/reference ships them, or rendered into it). Needs a
// current GL context where techniques are drawn.
std::vector<ClarityResult> run_clarity(const ClarityOptions& options,
                                       const std::function<ImageRGB(const Scene&)>& truth);

// The contrast of a drawing over both grounds, its visibility per channel.
void measure_drawing(const std::vector<ClarityRow>& rows, ClarityDrawing& drawing);

// The tables as text (what the command prints) and as CSV (one line per
// view, row and drawing).
std::string clarity_text(const std::vector<ClarityResult>& results);
std::string clarity_csv(const std::vector<ClarityResult>& results);

}  // namespace planet
