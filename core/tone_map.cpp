#include "core/tone_map.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

using namespace glm;
using Real = double;
using Real3 = glm::dvec3;
#include "core/shaders/tone_map.glsl"

}  // namespace

std::vector<uint8_t> tone_mapped_rgb8(const ImageRGB& image, double exposure) {
  std::vector<uint8_t> rgb(image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); i += 3) {
    // Negative radiance (an error image's sign) is black, not the curve's
    // far side.
    Real3 exposed(std::max(0.0, double(image.pixels[i]) * exposure),
                  std::max(0.0, double(image.pixels[i + 1]) * exposure),
                  std::max(0.0, double(image.pixels[i + 2]) * exposure));
    Real3 color = tone_map(exposed);
    for (int c = 0; c < 3; ++c) rgb[i + size_t(c)] = uint8_t(std::lround(255.0 * color[c]));
  }
  return rgb;
}

void write_tone_mapped_png(const std::filesystem::path& file, const ImageRGB& image,
                           double exposure) {
  write_png_rgb8(file, image.width, image.height, tone_mapped_rgb8(image, exposure));
}

}  // namespace planet
