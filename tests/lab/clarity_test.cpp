// Daytime clarity (lab/clarity.h): the model's own figures, checked in
// closed form, and the ground truth's contrast against distance held to
// the model's transmittance (Koschmieder's law along the slant path).
#include "lab/clarity.h"
#include "lab/reference_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ClarityTest, KoschmiedersVisibilityIsLnFiftyOverTheModelsExtinction) {
  // Earth's green at the ground: Rayleigh 13.558e-6 /m and the aerosols'
  // 4.40e-6 (the ozone's tent starts at 10 km): ln(50) / 17.958e-6 m.
  Scene view = find_clarity_view("earth_6km");
  AtmosphereModel model = scene_atmosphere(view, scene_body(view));
  EXPECT_NEAR(koschmieder_visibility(model, 0.0).g, 3.912023 / 17.958e-6, 10.0);
  // At 6 km the aerosols are e^-5 of that, the air e^-0.75.
  double sigma = 13.558e-6 * std::exp(-0.75) + 4.40e-6 * std::exp(-5.0);
  EXPECT_NEAR(koschmieder_visibility(model, 6000.0).g, 3.912023 / sigma, 10.0);
}

TEST(ClarityTest, TheSteepestRaysDepthIsTheColumnBelowTheEyeOverItsCosine) {
  // From 6 km the air's column to the ground in green: Rayleigh's 13.558e-6
  // * 8 km * (1 - e^-0.75) and the aerosols' 4.40e-6 * 1.2 km * (1 - e^-5);
  // the steepest row, 59 deg down, sees it over the sine of its angle down
  // (a flat ground: the curvature shortens its 7 km by under 0.1 %).
  Scene view = find_clarity_view("earth_6km");
  std::vector<ClarityRow> rows = clarity_rows(view, 0);
  const ClarityRow& steep = rows.back();
  ASSERT_TRUE(steep.ground);
  double column =
      13.558e-6 * 8000.0 * (1.0 - std::exp(-0.75)) + 4.40e-6 * 1200.0 * (1.0 - std::exp(-5.0));
  double sine = std::sin(glm::radians(steep.depression_deg));
  EXPECT_NEAR(steep.tau.g, column / sine, 0.005 * column / sine);
  EXPECT_NEAR(steep.range_m, 6000.0 / sine, 0.01 * 6000.0 / sine);
}

TEST(ClarityTest, TheGroundTruthsTargetsFadeAsTheModelsTransmittanceAlongTheRay) {
  // Koschmieder's law on the slant path: a target's contrast is the view
  // path's transmittance, exp(-tau) of the model's own extinction, for the
  // truth (data/reference ships its renders) within its noise: four of its
  // standard errors (the two renders' and the targets' own radiance's,
  // taken as independent, which overstates it) and 0.003.
  const PathBudget paths = clarity_reference_paths();
  for (const Scene& view : clarity_views()) {
    ReferenceRender r[2];
    for (int g = 0; g < 2; ++g) {
      Scene s = clarity_scene(view, g == 0 ? kClarityDarkAlbedo : kClarityBrightAlbedo);
      ASSERT_TRUE(reference_cached(s, paths, ReferenceMode::kRgb))
          << view.name << ": its ground truth is not shipped in data/reference";
      r[g] = reference_render(s, paths);
    }
    std::vector<ClarityRow> rows = clarity_rows(view, 512);
    int checked = 0;
    double worst = 0;
    for (const ClarityRow& row : rows) {
      if (!row.ground) continue;
      glm::dvec3 c = contrast(row, r[0].image, r[1].image);
      glm::dvec3 dl = row_mean(r[1].image, row.row) - row_mean(r[0].image, row.row);
      glm::dvec3 dl0 = row.ground_bright - row.ground_dark;
      // The rows' noise: the mean of its pixels' over their count.
      glm::dvec3 noise2 = (row_mean(r[0].noise, row.row) * row_mean(r[0].noise, row.row) +
                           row_mean(r[1].noise, row.row) * row_mean(r[1].noise, row.row)) /
                          double(view.width);
      for (int k = 0; k < 3; ++k) {
        double sigma = std::abs(c[k]) *
                       std::sqrt(noise2[k] / (dl[k] * dl[k]) +
                                 row.ground_noise[k] * row.ground_noise[k] / (dl0[k] * dl0[k]));
        double t = std::exp(-row.tau[k]);
        EXPECT_NEAR(c[k], t, 4.0 * sigma + 0.003)
            << view.name << " row " << row.row << " (" << row.range_m / 1e3 << " km) "
            << "RGB"[k];
        worst = std::max(worst, std::abs(c[k] - t));
        ++checked;
      }
    }
    std::printf("%s: %d rows x channels, the truth's contrast within %.4f of exp(-tau)\n",
                view.name.c_str(), checked, worst);
    EXPECT_GT(checked, 3 * 30) << view.name;
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
