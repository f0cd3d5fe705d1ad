#pragma once
// The frame's tone map (core/shaders/tone_map.glsl) on the CPU, for images
// that never pass through a frame: the ground truth's PNGs.
#include "core/image_io.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace planet {

// Exposure, the ACES fit and sRGB encoding, as render/shaders/tonemap.frag
// gives them (without its dither): 8-bit RGB, rows as in the image.
std::vector<uint8_t> tone_mapped_rgb8(const ImageRGB& image, double exposure);

void write_tone_mapped_png(const std::filesystem::path& file, const ImageRGB& image,
                           double exposure);

}  // namespace planet
