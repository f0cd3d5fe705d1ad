#pragma once
// Writing frames through OpenImageIO: linear radiance as EXR, tone-mapped
// colour as PNG. Files are written under a temporary name and renamed, so
// an interrupted write never leaves a file that looks finished.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace planet {

// `rgba` holds width*height RGBA floats with rows bottom-up (GL order);
// written as 32-bit float RGB, rows top-down.
void write_exr(const std::filesystem::path& file, int width, int height,
               const std::vector<float>& rgba);
// `rgba` holds width*height RGBA8 with rows bottom-up; written as RGB PNG.
void write_png(const std::filesystem::path& file, int width, int height,
               const std::vector<uint8_t>& rgba);

struct ImageRGB {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGB, rows top-down
};
ImageRGB read_image_rgb(const std::filesystem::path& file);

// Writes text under a temporary name and renames it into place.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace planet
