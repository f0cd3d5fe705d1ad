#pragma once
// The error image a person looks at (|technique - reference| / mean
// reference, per channel), with its colour scale drawn below it: without
// one, a bright pixel could be 5 % or 50 %.
#include "core/image_io.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace planet {

// The error images' exposure: 10 % of the mean is a bright grey.
constexpr double kErrorExposure = 5.0;
// The scale's numbered ticks, as fractions of the mean reference.
constexpr std::array<double, 6> kErrorScaleTicks = {0, 0.01, 0.02, 0.05, 0.10, 0.50};

struct ErrorScaleLayout {
  int bar_top = 0, bar_bottom = 0;  // rows of the bar, [top, bottom)
  int labels_top = 0;               // the first row of the numbers
  std::vector<int> tick_columns;    // one per kErrorScaleTicks
};

// `error` enlarged (accuracy.h's enlarged) and tone-mapped at
// kErrorExposure, over a white band that holds the scale: a caption, a bar
// of the colours an error equal in the three channels takes, its ticks
// evenly spaced (between them the error grows linearly), and their numbers
// in percent. RGB8 rows top-down; `layout` says where the bar is.
std::vector<uint8_t> error_image_with_scale(const ImageRGB& error, int& width, int& height,
                                            ErrorScaleLayout* layout = nullptr);

void write_error_png(const std::filesystem::path& file, const ImageRGB& error);

}  // namespace planet
