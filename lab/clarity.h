#pragma once
// Daytime clarity: how far the ground shows through the air. A view looks
// down at a smooth ground from a height (6 km and 400 km over Earth, 10 km
// over Mars), one row of pixels per distance, and is drawn twice: where
// each ray meets the ground, a dark target and a bright one, each too
// small to light the air around it, which the ground of the model's own
// albedo lights. The air's light along a ray is then the same over both,
// and the difference of the two radiances is the targets' carried by the
// air:
//
//     L_bright - L_dark = C * (L0_bright - L0_dark)
//
// with L0 a target's radiance where the ray meets it (traced from 1 m
// above it) and C the contrast transmittance, which is the view path's
// transmittance exp(-tau), tau the model's extinction integrated along
// the ray: Koschmieder's law, C = exp(-sigma x) along a level path of
// uniform air, on a slant path. The visibility is where C falls to 2 %, x
// = ln(50) / sigma along a level path (docs/surfaces.md#clarity).
//
// Over two uniform grounds of those albedos instead (`uniform`), the
// bright ground lights the air above it too, and the difference holds
// more than the transmittance: a large field of snow beside a forest
// keeps more contrast than a small target does.
#include "lab/scene.h"

#include <string>
#include <vector>

namespace planet {

// The two grounds, their albedo at every wavelength: a conifer forest's
// and dry snow's order (docs/surfaces.md#materials).
constexpr double kClarityDarkAlbedo = 0.05, kClarityBrightAlbedo = 0.5;
// The contrast at which the ground counts as seen (the meteorological
// visibility's 2 %, WMO's Guide to Instruments, CIMO, chapter 9).
constexpr double kClarityThreshold = 0.02;

// The views: earth_6km, earth_400km and mars_10km, each a narrow column
// (8x64) looking down from the horizon's sky toward the nadir, the sun 25
// deg up behind the camera's right as in the ascent flight.
std::vector<Scene> clarity_views();
// A view by name; InputError naming the known ones otherwise.
Scene find_clarity_view(const std::string& name);
// The view with a target of this albedo where each ray meets the ground
// (uniform: the whole ground of it). Its name, and so the tracer's random
// streams, stay the view's: the two targets' renders share their paths'
// numbers, and the noise of their difference is smaller than either's.
Scene clarity_scene(const Scene& view, double albedo, bool uniform = false);
// Paths per pixel of the views' ground truths (data/reference ships them).
PathBudget clarity_reference_paths();

// One row of a view: its central ray and what the model and the ground
// truth give along it, per channel (red, green, blue).
struct ClarityRow {
  int row = 0;
  bool ground = false;          // the ray meets the ground
  double range_m = 0;           // from the eye to the ground along the ray
  double depression_deg = 0;    // the ray below the eye's horizontal
  glm::dvec3 tau{0.0};          // the model's extinction along it to the ground
  glm::dvec3 ground_dark{0.0};  // L0 of the dark target, traced from 1 m above it
  glm::dvec3 ground_bright{0.0};
  glm::dvec3 ground_noise{0.0};  // the standard error of L0_bright - L0_dark
};

// The rows of a view: geometry, the model's optical depths, and the ground
// truth's L0 of both targets at `paths` paths per channel (all cores; none
// where `paths` is 0).
std::vector<ClarityRow> clarity_rows(const Scene& view, int paths = 2048, bool uniform = false);

// A row's contrast transmittance: (L_bright - L_dark) / (L0_bright -
// L0_dark), the rows' mean radiance over the columns of each image.
glm::dvec3 row_mean(const ImageRGB& image, int row);
glm::dvec3 contrast(const ClarityRow& row, const ImageRGB& dark, const ImageRGB& bright);

// The range (m) at which a channel's contrast first falls to the threshold
// going away from the eye over the ground rows, interpolated in its
// logarithm between rows; negative where it never does before the
// horizon, in which case `at_horizon` holds the contrast there.
double visibility_range(const std::vector<ClarityRow>& rows, const std::vector<double>& contrasts,
                        double& at_horizon);
// The same range by the model's transmittance exp(-tau) alone.
std::vector<double> model_transmittance(const std::vector<ClarityRow>& rows, int channel);
// Koschmieder's visibility, ln(50) / sigma, for the model's extinction at
// an altitude over the bottom, per channel.
glm::dvec3 koschmieder_visibility(const AtmosphereModel& model, double altitude_m);

}  // namespace planet
