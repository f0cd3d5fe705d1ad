#include "lab/error_png.h"

#include "core/tone_map.h"
#include "lab/accuracy.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace planet {

namespace {

// A 5x7 pixel font of the characters the scale writes: each glyph's rows,
// top to bottom, '#' for ink.
const std::map<char, std::array<const char*, 7>>& glyphs() {
  static const std::map<char, std::array<const char*, 7>> font = {
      {'0', {" ### ", "#   #", "#  ##", "# # #", "##  #", "#   #", " ### "}},
      {'1', {"  #  ", " ##  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
      {'2', {" ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####"}},
      {'3', {"#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### "}},
      {'4', {"   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # "}},
      {'5', {"#####", "#    ", "#### ", "    #", "    #", "#   #", " ### "}},
      {'6', {"  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### "}},
      {'7', {"#####", "    #", "   # ", "  #  ", " #   ", " #   ", " #   "}},
      {'8', {" ### ", "#   #", "#   #", " ### ", "#   #", "#   #", " ### "}},
      {'9', {" ### ", "#   #", "#   #", " ####", "    #", "   # ", " ##  "}},
      {'%', {"##   ", "##  #", "   # ", "  #  ", " #   ", "#  ##", "   ##"}},
      {' ', {"     ", "     ", "     ", "     ", "     ", "     ", "     "}},
      {'A', {" ### ", "#   #", "#   #", "#####", "#   #", "#   #", "#   #"}},
      {'C', {" ### ", "#   #", "#    ", "#    ", "#    ", "#   #", " ### "}},
      {'E', {"#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#####"}},
      {'F', {"#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#    "}},
      {'H', {"#   #", "#   #", "#   #", "#####", "#   #", "#   #", "#   #"}},
      {'I', {" ### ", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
      {'M', {"#   #", "## ##", "# # #", "# # #", "#   #", "#   #", "#   #"}},
      {'N', {"#   #", "#   #", "##  #", "# # #", "#  ##", "#   #", "#   #"}},
      {'O', {" ### ", "#   #", "#   #", "#   #", "#   #", "#   #", " ### "}},
      {'R', {"#### ", "#   #", "#   #", "#### ", "# #  ", "#  # ", "#   #"}},
      {'T', {"#####", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", "  #  "}},
  };
  return font;
}

constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;

struct Canvas {
  int width, height;
  std::vector<uint8_t> rgb;
  void set(int x, int y, uint8_t r, uint8_t g, uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
    rgb[i] = r, rgb[i + 1] = g, rgb[i + 2] = b;
  }
  void fill(int x0, int y0, int x1, int y1, uint8_t v) {
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) set(x, y, v, v, v);
    }
  }
  // Black text, `scale` pixels a font pixel, its top left at (x, y).
  void text(const std::string& s, int x, int y, int scale) {
    for (char c : s) {
      const auto& rows = glyphs().at(c);
      for (int gy = 0; gy < kGlyphHeight; ++gy) {
        for (int gx = 0; gx < kGlyphWidth; ++gx) {
          if (rows[size_t(gy)][gx] == '#') {
            fill(x + gx * scale, y + gy * scale, x + (gx + 1) * scale, y + (gy + 1) * scale, 0);
          }
        }
      }
      x += kGlyphAdvance * scale;
    }
  }
};

int text_width(const std::string& s, int scale) {
  return s.empty() ? 0 : (int(s.size()) * kGlyphAdvance - 1) * scale;
}

// The colour of an error equal in the three channels.
std::array<uint8_t, 3> error_colour(double error) {
  ImageRGB pixel{1, 1, {float(error), float(error), float(error)}};
  std::vector<uint8_t> rgb = tone_mapped_rgb8(pixel, kErrorExposure);
  return {rgb[0], rgb[1], rgb[2]};
}

}  // namespace

std::vector<uint8_t> error_image_with_scale(const ImageRGB& error, int& width, int& height,
                                            ErrorScaleLayout* layout) {
  ImageRGB big = enlarged(error);
  std::vector<uint8_t> image = tone_mapped_rgb8(big, kErrorExposure);
  // The band: a caption, the bar, its ticks and numbers, at twice the
  // font's size where the image is wide enough (the enlarged ones are).
  const int scale = big.width >= 256 ? 2 : 1;
  const std::string caption = "ERROR IN % OF THE MEAN REFERENCE";
  const int caption_scale = text_width(caption, scale) + 8 <= big.width ? scale : 1;
  const int pad = 4 * scale, bar_height = 7 * scale, tick = 3 * scale;
  const int caption_top = pad, bar_top = caption_top + kGlyphHeight * caption_scale + pad;
  const int bar_bottom = bar_top + bar_height, labels_top = bar_bottom + tick + 2 * scale;
  const int band = labels_top + kGlyphHeight * scale + pad;
  Canvas canvas{big.width, big.height + band, {}};
  canvas.rgb.assign(size_t(canvas.width) * size_t(canvas.height) * 3, 255);
  std::copy(image.begin(), image.end(), canvas.rgb.begin());
  const int top = big.height;
  canvas.text(caption, pad, top + caption_top, caption_scale);

  // The bar between margins that hold half the widest number at each end.
  const int margin = text_width("50%", scale) / 2 + pad;
  const int left = margin, right = big.width - 1 - margin;  // the first and last ticks' columns
  const int steps = int(kErrorScaleTicks.size()) - 1;
  auto tick_column = [&](int k) {
    return left + int(std::lround(double(k) * (right - left) / steps));
  };
  for (int x = left; x <= right; ++x) {
    // Linear in the error between neighbouring ticks.
    double at = double(x - left) / (right - left) * steps;
    int k = std::min(int(at), steps - 1);
    double v = kErrorScaleTicks[size_t(k)] +
               (at - k) * (kErrorScaleTicks[size_t(k) + 1] - kErrorScaleTicks[size_t(k)]);
    if (x == tick_column(k + 1)) v = kErrorScaleTicks[size_t(k) + 1];
    if (x == tick_column(k)) v = kErrorScaleTicks[size_t(k)];
    std::array<uint8_t, 3> c = error_colour(v);
    for (int y = top + bar_top; y < top + bar_bottom; ++y) canvas.set(x, y, c[0], c[1], c[2]);
  }
  // Its frame, so that its black and white ends show against the band.
  for (int x = left - 1; x <= right + 1; ++x) {
    canvas.set(x, top + bar_top - 1, 0, 0, 0);
    canvas.set(x, top + bar_bottom, 0, 0, 0);
  }
  for (int y = top + bar_top - 1; y <= top + bar_bottom; ++y) {
    canvas.set(left - 1, y, 0, 0, 0);
    canvas.set(right + 1, y, 0, 0, 0);
  }
  if (layout) {
    layout->bar_top = top + bar_top;
    layout->bar_bottom = top + bar_bottom;
    layout->labels_top = top + labels_top;
    layout->tick_columns.clear();
  }
  for (int k = 0; k <= steps; ++k) {
    int x = tick_column(k);
    canvas.fill(x - scale / 2, top + bar_bottom, x - scale / 2 + scale, top + bar_bottom + tick, 0);
    std::string label = fmt::format("{:g}%", 100 * kErrorScaleTicks[size_t(k)]);
    if (k == 0) label = "0";
    canvas.text(label, x - text_width(label, scale) / 2, top + labels_top, scale);
    if (layout) layout->tick_columns.push_back(x);
  }
  width = canvas.width;
  height = canvas.height;
  return canvas.rgb;
}

void write_error_png(const std::filesystem::path& file, const ImageRGB& error) {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb = error_image_with_scale(error, width, height);
  write_png_rgb8(file, width, height, rgb);
}

}  // namespace planet
