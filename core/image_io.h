#pragma once
// Images in and out through OpenImageIO: linear radiance as EXR, tone-mapped
// colour as PNG. Files are written under a temporary name and renamed, so
// an interrupted write never leaves a file that looks finished.
#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace planet {

struct ImageRGB {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGB, rows top-down
};

// GL's RGBA rows, bottom-up as a texture reads back, as RGB rows top-down:
// the one place rows are flipped.
template <typename T>
std::vector<T> rgb_rows_from_gl(int width, int height, const std::vector<T>& rgba) {
  std::vector<T> rgb(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y) {
    const T* src = rgba.data() + size_t(height - 1 - y) * size_t(width) * 4;
    T* dst = rgb.data() + size_t(y) * size_t(width) * 3;
    for (int x = 0; x < width; ++x) {
      dst[3 * x + 0] = src[4 * x + 0];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
  return rgb;
}

inline ImageRGB image_from_gl(int width, int height, const std::vector<float>& rgba) {
  return {width, height, rgb_rows_from_gl(width, height, rgba)};
}

// A named value an EXR carries in its header: an OpenEXR standard
// attribute (capDate, latitude, worldToCamera, ...) or one of our own
// ("planet:..."). Matrices map column vectors, as GLM's do.
struct ImageAttribute {
  std::string name;
  std::variant<double, float, std::string, glm::dvec3, glm::mat4> value;
};

// What a frame's EXR holds beyond its colour: header attributes, and a
// depth channel Z (distance along each pixel's ray, metres; +inf where the
// ray meets nothing), GL rows bottom-up like the colour. Without "DateTime"
// among the attributes the header gets a fixed date, never the wall
// clock's: the same frame gives the same bytes.
struct ExrExtras {
  std::vector<ImageAttribute> attributes;
  std::vector<float> depth;  // empty: no Z channel
};

// 32-bit float RGB EXR.
void write_exr(const std::filesystem::path& file, const ImageRGB& image);
// `rgba` holds width*height RGBA floats with rows bottom-up (GL order).
void write_exr(const std::filesystem::path& file, int width, int height,
               const std::vector<float>& rgba, const ExrExtras& extras = {});
// `rgb` holds width*height RGB8, rows top-down.
void write_png_rgb8(const std::filesystem::path& file, int width, int height,
                    const std::vector<uint8_t>& rgb);
// `rgba` holds width*height RGBA8 with rows bottom-up (GL order).
void write_png(const std::filesystem::path& file, int width, int height,
               const std::vector<uint8_t>& rgba);

// Refuses (InputError naming the file and `what` reads it) a file whose
// first bytes are not those of a PNG, TIFF, OpenEXR or PNM image, before
// OpenImageIO sees it: its readers of other formats are not all safe on
// malformed files (2.4's JPEG reader overflows a buffer on a bad IPTC
// block; found by the height_map fuzz target).
void check_image_signature(const std::filesystem::path& file, const std::string& what);

// The most values (pixels times channels) an image read whole may hold:
// 2^27, a 16384x8192 height map of one channel (512 MiB as floats).
constexpr long long kMaxImageValues = 1LL << 27;

// Refuses (InputError naming the file and `what` reads it) an image whose
// header declares no pixels or more than kMaxImageValues, before anything
// is allocated for it: a header of a few bytes can declare terabytes
// (found by the height_map fuzz target).
void check_image_size(const std::filesystem::path& file, const std::string& what, long long width,
                      long long height, long long channels);

ImageRGB read_image_rgb(const std::filesystem::path& file);

}  // namespace planet
