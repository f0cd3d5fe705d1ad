#pragma once
// What a viewer sees differ between two tone-mapped images: CIEDE2000
// (Sharma, Wu and Dalal 2005) between their sRGB pixels, through CIELAB
// under D65.
#include <array>
#include <cstdint>
#include <vector>

namespace planet {

using Lab = std::array<double, 3>;  // L*, a*, b*

// An 8-bit sRGB colour in CIELAB (D65 white).
Lab lab_from_srgb8(uint8_t r, uint8_t g, uint8_t b);
// CIEDE2000 with kL = kC = kH = 1.
double ciede2000(const Lab& one, const Lab& two);
// The mean CIEDE2000 of two 8-bit RGB images of the same size (rows of
// r, g, b bytes) over the pixels with mask 0 (empty mask: all of them).
double mean_ciede2000(const std::vector<uint8_t>& one, const std::vector<uint8_t>& two,
                      const std::vector<uint8_t>& mask);

}  // namespace planet
