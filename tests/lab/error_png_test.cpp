// The accuracy command's error PNG carries its colour scale: below the
// enlarged image, a bar whose column at each numbered tick is the colour of
// that error (equal in the three channels), growing from black at 0 to the
// brightest at 50 %, with the numbers' ink beneath each tick.
#include "lab/error_png.h"

#include <gtest/gtest.h>

#include "core/tone_map.h"
#include "lab/accuracy.h"
#include "tests/unity_id.h"

#include <cmath>
#include <filesystem>

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ErrorPngTest, AccuracysErrorImageHasItsScale) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "planet_error_png_test";
  std::filesystem::remove_all(dir);
  Scene scene;
  scene.name = "ramp";
  ImageRGB image{32, 16, std::vector<float>(32 * 16 * 3, 0.1f)};
  TechniqueAccuracy accuracy;
  accuracy.signed_error = image;
  for (size_t i = 0; i < accuracy.signed_error.pixels.size(); ++i) {
    accuracy.signed_error.pixels[i] = 0.002f * float(i % 96);  // 0 to 19 %
  }
  write_accuracy_images(dir, scene, image, image, accuracy);
  ImageRGB png = read_image_rgb(dir / "ramp_error.png");
  std::filesystem::remove_all(dir);

  // The enlarged image (256x128), and the band of the scale below it.
  ASSERT_EQ(png.width, 256);
  ASSERT_GT(png.height, 128 + 20) << "no scale below the error image";
  int width = 0, height = 0;
  ErrorScaleLayout layout;
  error_image_with_scale(accuracy.signed_error, width, height, &layout);
  ASSERT_EQ(height, png.height);
  ASSERT_EQ(layout.tick_columns.size(), kErrorScaleTicks.size());
  auto at = [&](int x, int y, int c) {
    return int(
        std::lround(255 * png.pixels[(size_t(y) * size_t(png.width) + size_t(x)) * 3 + size_t(c)]));
  };
  double last = -1;
  for (size_t k = 0; k < kErrorScaleTicks.size(); ++k) {
    ImageRGB pixel{1, 1, std::vector<float>(3, float(kErrorScaleTicks[k]))};
    std::vector<uint8_t> expected = tone_mapped_rgb8(pixel, kErrorExposure);
    int x = layout.tick_columns[k];
    for (int y = layout.bar_top; y < layout.bar_bottom; ++y) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(at(x, y, c), expected[size_t(c)])
            << "bar column " << x << " row " << y << ", the tick of " << 100 * kErrorScaleTicks[k]
            << " %";
      }
    }
    EXPECT_GT(at(x, layout.bar_top, 0), last) << "the bar does not brighten with the error";
    last = at(x, layout.bar_top, 0);
    // The number's ink: black pixels below the tick, on the white band.
    int ink = 0;
    for (int y = layout.labels_top; y < png.height; ++y) {
      for (int dx = -3; dx <= 3; ++dx) ink += at(x + dx, y, 0) == 0 ? 1 : 0;
    }
    EXPECT_GT(ink, 10) << "no number under the tick of " << 100 * kErrorScaleTicks[k] << " %";
  }
  EXPECT_EQ(at(layout.tick_columns.front(), layout.bar_top, 0), 0);  // no error: black
  EXPECT_EQ(at(2, png.height - 2, 0), 255);                          // the band is white
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
