// Each technique confined to single scattering (the registry's
// single_scattering settings, the ground lit by the sun alone) against the
// ground truth's first order (`reference --max-order 1`, shipped for six
// scenes): the half of the lab's split by order that says how well a
// technique does what single scattering asks of it. A regression guard per
// channel, as technique_accuracy_gl_test.cpp's.
#include "gl/context.h"
#include "lab/accuracy.h"
#include "lab/gpu/scene_render.h"
#include "lab/reference_cache.h"
#include "tests/atmosphere/accuracy_guard.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

struct FirstOrderCase {
  const char* technique;
  const char* scene;
  // Relative RMSE in % (R / G / B) against the first order, measured here
  // (the test prints them). oneil's sunsets and the asteroid's tint miss
  // the absorber its model has not; bruneton:cheap's 16 altitudes miss the
  // asteroid's thin shell.
  std::array<double, 3> today;
};

// clang-format off
const FirstOrderCase kCases[] = {
    {"raymarch", "earth_noon", {1.06, 0.754, 0.615}},
    {"hillaire", "earth_noon", {1.02, 0.734, 0.588}},
    {"hillaire2020", "earth_noon", {1.02, 0.734, 0.588}},
    {"bruneton:cheap", "earth_noon", {1.02, 0.719, 0.564}},
    {"oneil", "earth_noon", {2.99, 5.3, 3.23}},
    {"raymarch", "earth_sunset", {0.995, 0.827, 0.48}},
    {"hillaire", "earth_sunset", {0.21, 0.347, 0.418}},
    {"bruneton:cheap", "earth_sunset", {1.1, 0.389, 0.6}},
    {"oneil", "earth_sunset", {29.7, 57.8, 2.42}},
    {"raymarch", "mars_noon", {0.539, 0.447, 0.463}},
    {"hillaire", "mars_noon", {0.667, 0.633, 0.631}},
    {"bruneton:cheap", "mars_noon", {0.274, 0.355, 0.468}},
    {"oneil", "mars_noon", {2.24, 2.13, 1.98}},
    {"raymarch", "mars_sunset", {0.621, 0.745, 0.829}},
    {"hillaire", "mars_sunset", {1.26, 1.02, 0.95}},
    {"bruneton:cheap", "mars_sunset", {4.28, 5.61, 6.82}},
    {"oneil", "mars_sunset", {1.73, 1.28, 1.79}},
    {"raymarch", "asteroid_surface", {0.0839, 0.112, 0.214}},
    {"hillaire", "asteroid_surface", {0.237, 0.152, 0.14}},
    {"bruneton:cheap", "asteroid_surface", {0.47, 0.654, 0.462}},
    {"oneil", "asteroid_surface", {10.2, 30.1, 1.85}},
    {"raymarch", "asteroid_space", {0.47, 0.261, 0.196}},
    {"hillaire", "asteroid_space", {0.368, 0.417, 0.0764}},
    {"bruneton:cheap", "asteroid_space", {9.29, 7.51, 8.06}},
    {"oneil", "asteroid_space", {42.8, 125, 7.12}},
};
// clang-format on

// O'Neil's scale function fixed to Earth's 25 % / 2.5 % ratio (the
// chapter's polynomial), a known failure the stability map pins: on Mars
// and the asteroid its single scattering is several times the fitted
// one's error. Held from both sides, so that a change that moves it is seen.
// clang-format off
const FirstOrderCase kPinnedFailures[] = {
    {"oneil:scale=chapter", "mars_noon", {8.72, 7.6, 7.08}},
    {"oneil:scale=chapter", "asteroid_surface", {28.2, 37.4, 42.4}},
};
// clang-format on

// Relative RMSE per channel in %, printed as a row of the tables above.
std::array<double, 3> first_order_error(const FirstOrderCase& c) {
  Scene scene = find_scene(c.scene, 32, 16);
  scene.max_order = 1;
  ImageRGB reference = reference_image(scene, PathBudget(65536));
  TechniqueAccuracy accuracy =
      measure_accuracy(scene, render_first_order_with(scene, c.technique), reference);
  std::array<double, 3> e;
  for (int k = 0; k < 3; ++k) e[k] = 100 * accuracy.channels[k].relative();
  std::printf("    {\"%s\", \"%s\", {%.3g, %.3g, %.3g}},\n", c.technique, c.scene, e[0], e[1],
              e[2]);
  return e;
}

TEST(FirstOrderGLTest, EachTechniquesSingleScatteringMatchesTheGroundTruthsFirstOrder) {
  auto context = GlContext::create_headless();
  for (const FirstOrderCase& c : kCases) {
    std::array<double, 3> e = first_order_error(c);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(e[k], allowed_percent(c.today[k])) << c.technique << " " << c.scene << " " << "RGB"[k];
    }
  }
}

TEST(FirstOrderGLTest, TheChaptersScaleFunctionFailsOffEarthsRatio) {
  auto context = GlContext::create_headless();
  for (const FirstOrderCase& c : kPinnedFailures) {
    std::array<double, 3> e = first_order_error(c);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(e[k], allowed_percent(c.today[k])) << c.technique << " " << c.scene << " " << "RGB"[k];
      EXPECT_GE(e[k], 0.8 * c.today[k] - 0.2) << c.technique << " " << c.scene << " " << "RGB"[k];
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
