// The stability map's plan, shards, classes and the model variants its
// axes make: what a user of `planet lab stability` relies on before any
// render.
#include "atmosphere/model.h"
#include "core/error.h"
#include "lab/stability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// The vertical optical depth of a component from the bottom to the top, by
// the midpoint rule.
double vertical_depth(const AtmosphereModel& m, const AtmosphereComponent& c, int channel) {
  const int n = 20000;
  double h = (m.top_radius - m.bottom_radius) / n, sum = 0;
  for (int i = 0; i < n; ++i) sum += density_at(c.density, (i + 0.5) * h);
  return sum * h * c.extinction()[channel];
}

AtmosphereModel earth() { return load_atmosphere(load_body(find_body_file("earth"))); }

TEST(StabilityModelTest, AnotherRadiusAtTheThicknessRatioKeepsEveryVerticalOpticalDepth) {
  AtmosphereModel m = earth();
  for (double radius : {1e4, 1e6, 7e7}) {
    AtmosphereModel v = with_bottom_radius(m, radius, false);
    EXPECT_DOUBLE_EQ(v.bottom_radius, radius);
    EXPECT_NEAR((v.top_radius - v.bottom_radius) / v.bottom_radius,
                (m.top_radius - m.bottom_radius) / m.bottom_radius, 1e-12);
    for (auto part : {&AtmosphereModel::rayleigh, &AtmosphereModel::mie, &AtmosphereModel::absorber}) {
      for (int c = 0; c < 3; ++c) {
        double want = vertical_depth(m, m.*part, c);
        EXPECT_NEAR(vertical_depth(v, v.*part, c), want, 1e-6 * want + 1e-12) << radius;
      }
    }
  }
}

TEST(StabilityModelTest, AnotherRadiusAtTheAbsoluteThicknessKeepsTheShellInMetres) {
  AtmosphereModel m = earth();
  AtmosphereModel v = with_bottom_radius(m, 1e5, true);
  EXPECT_DOUBLE_EQ(v.top_radius - v.bottom_radius, m.top_radius - m.bottom_radius);
  EXPECT_EQ(v.rayleigh.scattering, m.rayleigh.scattering);
  EXPECT_EQ(v.rayleigh.density.layers[1].exp_scale, m.rayleigh.density.layers[1].exp_scale);
}

TEST(StabilityModelTest, StretchedScaleHeightsKeepTheColumnAndChangeTheProfile) {
  AtmosphereModel m = earth();
  for (double f : {0.25, 4.0, 10.0}) {
    AtmosphereModel v = with_scale_heights_scaled(m, f);
    EXPECT_NEAR(-1.0 / v.rayleigh.density.layers[1].exp_scale, 8000.0 * f, 1e-6);
    for (int c = 0; c < 3; ++c) {
      double want = vertical_depth(m, m.rayleigh, c);
      EXPECT_NEAR(vertical_depth(v, v.rayleigh, c), want, 1e-4 * want) << f;
      want = vertical_depth(m, m.mie, c);
      EXPECT_NEAR(vertical_depth(v, v.mie, c), want, 1e-4 * want) << f;
    }
    // The absorber's tent is no exponential: left as it is.
    EXPECT_EQ(v.absorber.absorption, m.absorber.absorption);
  }
}

TEST(StabilityModelTest, DensityScalesScatteringAndAbsorptionAlike) {
  AtmosphereModel m = earth();
  AtmosphereModel v = with_absorption_scaled(with_scattering_scaled(m, 50.0), 50.0);
  EXPECT_NEAR(v.rayleigh.scattering.z, 50.0 * m.rayleigh.scattering.z, 1e-15);
  EXPECT_NEAR(v.mie.absorption.x, 50.0 * m.mie.absorption.x, 1e-15);
  EXPECT_NEAR(v.absorber.absorption.y, 50.0 * m.absorber.absorption.y, 1e-15);
  ASSERT_TRUE(v.spectrum.has_value());
  EXPECT_NEAR(v.spectrum->absorber_absorption[10], 50.0 * m.spectrum->absorber_absorption[10],
              1e-15);
}

TEST(StabilityPlanTest, EveryCellIsOneViewNamedForWhatItChanges) {
  StabilityOptions o;
  std::vector<StabilityCell> cells = plan_stability(o);
  std::set<std::string> names;
  for (const StabilityCell& c : cells) {
    EXPECT_TRUE(names.insert(c.scene.name).second) << c.scene.name;
    EXPECT_FALSE(c.slices.empty());
    EXPECT_EQ(c.scene.width, kStabilityWidth);
    EXPECT_EQ(c.scene.height, kStabilityHeight);
  }
  // 3 bodies x (the preset, 47 one-axis values, 16 + 20 on the planes, of
  // which the plane's density 10 and 100 at no other g are not new: none).
  EXPECT_EQ(cells.size(), 3u * 80u);
  EXPECT_TRUE(names.count("stability-earth-d50"));
  EXPECT_TRUE(names.count("stability-mars-g0.99"));
  EXPECT_TRUE(names.count("stability-asteroid-r7e7-z1e8"));
  EXPECT_TRUE(names.count("stability-earth-ra10000"));
  EXPECT_TRUE(names.count("stability-earth-z-1000"));
  // The preset is on every one-axis sweep.
  EXPECT_EQ(cells.front().scene.name, "stability-earth-preset");
  EXPECT_EQ(cells.front().slices.size(), 7u);
}

TEST(StabilityPlanTest, ShardsSplitTheCellsWithoutOverlapOrGap) {
  std::vector<StabilityCell> cells = plan_stability(StabilityOptions{});
  for (int n : {1, 2, 7}) {
    std::multiset<std::string> seen;
    for (int k = 1; k <= n; ++k) {
      for (const StabilityCell& c : shard_cells(cells, k, n)) seen.insert(c.scene.name);
    }
    EXPECT_EQ(seen.size(), cells.size());
    for (const StabilityCell& c : cells) EXPECT_EQ(seen.count(c.scene.name), 1u);
  }
  EXPECT_EQ(parse_shard("2/5"), std::make_pair(2, 5));
  for (const char* bad : {"0/3", "4/3", "1", "a/b", "1/0", "2/3x", ""}) {
    EXPECT_THROW(parse_shard(bad), InputError) << bad;
  }
}

TEST(StabilityPlanTest, BadNamesAndValuesFailBeforeAnyWork) {
  StabilityOptions o;
  o.bodies = {"venus"};
  EXPECT_THROW(plan_stability(o), InputError);
  o = {};
  o.budget_percent = 0;
  EXPECT_THROW(plan_stability(o), InputError);
  o = {};
  EXPECT_THROW(named_cells(plan_stability(o), {"stability-earth-d7"}), InputError);
}

TEST(StabilityPlanTest, TheViewFollowsTheShellFromTheGroundToDeepSpace) {
  // From the ground the camera looks 35 degrees up; from 1e9 m straight
  // down at a disc a fraction of a degree across.
  Scene ground = stability_scene("earth", StabilityPoint{}, 16, 8);
  StabilityPoint far;
  far.altitude_m = 1e9;
  Scene space = stability_scene("earth", far, 16, 8);
  EXPECT_NEAR(ground.camera.vertical_fov, glm::radians(90.0), 1e-9);
  EXPECT_LT(space.camera.vertical_fov, glm::radians(1.0));
  EXPECT_GT(space.camera.vertical_fov, glm::radians(0.5));
  EXPECT_NEAR(glm::length(space.camera.pos_body), 1e9 + 6.37e6, 2e4);
}

ImageRGB flat(float v) {
  ImageRGB image;
  image.width = 4;
  image.height = 2;
  image.pixels.assign(4 * 2 * 3, v);
  return image;
}

Scene tiny_scene() { return stability_scene("earth", StabilityPoint{}, 4, 2); }

TEST(StabilityClassTest, EachClassFromTheValuesThatMakeIt) {
  Scene scene = tiny_scene();
  scene.sun_dir_body = -scene.camera.pos_body;  // no sun disk in view
  ImageRGB reference = flat(0.1f), noise = flat(0.0f);
  EXPECT_EQ(classify(scene, flat(0.101f), &reference, &noise, 5.0).cls, StabilityClass::kOk);
  StabilityResult off = classify(scene, flat(0.12f), &reference, &noise, 5.0);
  EXPECT_EQ(off.cls, StabilityClass::kInaccurate);
  EXPECT_NEAR(off.worst(), 0.2, 1e-5);
  ImageRGB nan = flat(0.1f);
  nan.pixels[7] = std::nanf("");
  EXPECT_EQ(classify(scene, nan, &reference, &noise, 5.0).cls, StabilityClass::kNaN);
  ImageRGB inf = flat(0.1f);
  inf.pixels[0] = INFINITY;
  EXPECT_EQ(classify(scene, inf, &reference, &noise, 5.0).cls, StabilityClass::kNaN);
  ImageRGB negative = flat(0.1f);
  negative.pixels[4] = -0.01f;
  EXPECT_EQ(classify(scene, negative, &reference, &noise, 5.0).cls, StabilityClass::kExploded);
  ImageRGB bright = flat(0.1f);
  bright.pixels[5] = 1.5f;
  StabilityResult blown = classify(scene, bright, &reference, &noise, 5.0);
  EXPECT_EQ(blown.cls, StabilityClass::kExploded);
  EXPECT_NEAR(blown.worst_ratio, 15.0, 1e-4);
  // With no ground truth (inside the planet), only the values count.
  EXPECT_EQ(classify(scene, flat(0.3f), nullptr, nullptr, 5.0).cls, StabilityClass::kOk);
  EXPECT_TRUE(std::isnan(classify(scene, flat(0.3f), nullptr, nullptr, 5.0).worst()));
  EXPECT_EQ(classify(scene, negative, nullptr, nullptr, 5.0).cls, StabilityClass::kExploded);
}

TEST(StabilityClassTest, ADarkSkyIsJudgedAgainstAFloorNotAgainstNothing) {
  // A reference of next to nothing (the sun far below the horizon): a
  // technique a thousandth of the sun's irradiance off is inaccurate,
  // one a billionth off is ok.
  Scene scene = tiny_scene();
  scene.sun_dir_body = -scene.camera.pos_body;
  ImageRGB reference = flat(1e-12f), noise = flat(0.0f);
  EXPECT_EQ(classify(scene, flat(1e-9f), &reference, &noise, 5.0).cls, StabilityClass::kOk);
  EXPECT_NE(classify(scene, flat(2e-3f), &reference, &noise, 5.0).cls, StabilityClass::kOk);
}

TEST(StabilityResultTest, AResultReadsBackAsItWasWritten) {
  StabilityResult r;
  r.cell = "stability-earth-d50";
  r.body = "earth";
  r.technique = "hillaire";
  r.quality = "default";
  r.choice = "hillaire";
  r.point.density = 50;
  r.point.mie_g = 0.95;
  r.slices = {"density"};
  r.cls = StabilityClass::kInaccurate;
  r.reason = "103 % over the 5 % budget";
  r.error = {0.03, 0.57, 1.03};
  StabilityResult back = result_from_json(result_to_json(r), "x.json");
  EXPECT_EQ(back.cls, r.cls);
  EXPECT_EQ(back.point.label(), "d50-g0.95");
  EXPECT_DOUBLE_EQ(back.worst(), 1.03);
  StabilityResult no_truth = r;
  no_truth.error = {std::nan(""), std::nan(""), std::nan("")};
  EXPECT_TRUE(std::isnan(result_from_json(result_to_json(no_truth), "x.json").worst()));
  EXPECT_THROW(result_from_json({{"cell", 3}}, "x.json"), InputError);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
