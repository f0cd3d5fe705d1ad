// The known failures of the techniques, each reproduced by one small cell
// of the stability map (16x8, its ground truth shipped in data/reference)
// and pinned to its measured class and error, so that a change that moves
// a failure, for better or for worse, is seen. Each figure is the worst
// channel's debiased relative RMSE per channel, in %, measured here (the
// test prints them); a pin holds within a fifth of its figure and 0.5
// points either way.
#include "gl/context.h"
#include "lab/accuracy.h"
#include "lab/gpu/scene_render.h"
#include "lab/reference_cache.h"
#include "lab/stability.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

struct Pin {
  const char* cell;
  const char* technique;
  StabilityClass cls;
  std::array<double, 3> error;  // %, R / G / B
  const char* why;
};

// clang-format off
const Pin kPins[] = {
    // Bruneton's orders in dense air: 4 orders leave most of the light out,
    // 20 bring red and green in; blue needs more still.
    {"stability-earth-d50", "bruneton:cheap,orders=4", StabilityClass::kInaccurate, {43.5, 88.2, 104}, "4 orders at 50x"},
    {"stability-earth-d50", "bruneton:cheap,orders=20", StabilityClass::kInaccurate, {16.3, 21.9, 98.9}, "20 orders at 50x"},
    // Hillaire 2020's isotropic multiple scattering: strong forward
    // scattering, and dense air (where the ground, lit by the frame's sky
    // light estimate, comes out ten times the truth).
    {"stability-earth-g0.95", "hillaire2020", StabilityClass::kInaccurate, {2.48, 5.15, 7.76}, "g 0.95"},
    {"stability-earth-d50", "hillaire2020", StabilityClass::kExploded, {44.9, 206, 113}, "50x"},
    // Ours: the orders above the sixth and their tail in dense air; the
    // Martian sunset's dust.
    // (At 50x, red was 4.21 % before the orders and the sky-view LUT read
    // the field at every other step; the map's classes did not move, nor
    // did they when the orders past the second went to a coarser grid.)
    {"stability-earth-d50", "hillaire", StabilityClass::kInaccurate, {7.48, 37.3, 101}, "50x"},
    {"stability-earth-d100", "hillaire", StabilityClass::kInaccurate, {25.7, 83.7, 104}, "100x"},
    {"stability-mars-s2", "hillaire", StabilityClass::kInaccurate, {7.69, 5.75, 0.0}, "Mars, sun 2 deg up"},
    // ... and what the map found: the dust's strong forward scattering
    // (its field is of degree 4; past g 0.9 the light it cannot hold is
    // spread over the sky), and the sky 10 degrees after sunset.
    {"stability-mars-g0.9", "hillaire", StabilityClass::kInaccurate, {19.2, 12.0, 5.64}, "Mars, g 0.9"},
    {"stability-mars-g0.99", "hillaire", StabilityClass::kExploded, {506, 383, 146}, "Mars, g 0.99"},
    {"stability-earth-s-10", "hillaire", StabilityClass::kInaccurate, {6.95, 1.44, 2.21}, "sun 10 deg down"},
    // The single-scattering techniques in dense air: the frame's estimate of
    // the sky's light on the ground has no attenuation of its own.
    {"stability-earth-d100", "raymarch", StabilityClass::kExploded, {139, 4230, 257}, "100x"},
    // O'Neil's scale function fixed to Earth's 25 % / 2.5 % ratio, on
    // bodies whose ratios differ, against the one fitted to each body (and
    // their single scattering alone: first_order_gl_test.cpp).
    {"stability-mars-preset", "oneil:scale=chapter", StabilityClass::kInaccurate, {67.7, 47.5, 29.4}, "Mars, chapter"},
    {"stability-mars-preset", "oneil", StabilityClass::kInaccurate, {69.7, 50.1, 32.6}, "Mars, fitted"},
    {"stability-asteroid-preset", "oneil:scale=chapter", StabilityClass::kInaccurate, {45.4, 57.2, 79.3}, "asteroid, chapter"},
    {"stability-asteroid-preset", "oneil", StabilityClass::kInaccurate, {28.5, 35.1, 68.3}, "asteroid, fitted"},
};
// clang-format on

double low_band(double today) { return 0.8 * today - 0.5; }
double high_band(double today) { return 1.2 * today + 0.5; }

TEST(StabilityPinsGLTest, EachKnownFailureStaysWhereTheMapFoundIt) {
  auto context = GlContext::create_headless();
  std::vector<StabilityCell> cells = plan_stability(StabilityOptions{});
  for (const Pin& pin : kPins) {
    StabilityCell cell = named_cells(cells, {pin.cell}).front();
    PathBudget budget = stability_reference_budget(cell);
    ASSERT_TRUE(reference_cached(cell.scene, budget, ReferenceMode::kRgb))
        << pin.cell << ": its ground truth is not shipped in data/reference";
    ReferenceRender truth = reference_render(cell.scene, budget);
    StabilityResult r = classify(cell.scene, render_scene_with(cell.scene, pin.technique),
                                 &truth.image, &truth.noise, 5.0);
    std::printf("    {\"%s\", \"%s\", %s, {%.3g, %.3g, %.3g}}\n", pin.cell, pin.technique,
                to_string(r.cls).c_str(), 100 * r.error[0], 100 * r.error[1], 100 * r.error[2]);
    EXPECT_EQ(r.cls, pin.cls) << pin.cell << " " << pin.technique << " (" << pin.why
                              << "): " << r.reason;
    for (int c = 0; c < 3; ++c) {
      if (pin.error[c] == 0) continue;  // blue on Mars at sunset: nothing left after noise
      double e = 100 * r.error[c];
      EXPECT_GE(e, low_band(pin.error[c])) << pin.cell << " " << pin.technique << " " << "RGB"[c];
      EXPECT_LE(e, high_band(pin.error[c])) << pin.cell << " " << pin.technique << " " << "RGB"[c];
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
