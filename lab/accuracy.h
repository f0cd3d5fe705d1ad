#pragma once
// A GPU atmosphere technique measured against the path-traced ground truth
// on a canonical scene: per channel, the RMSE and the RMSE relative to the
// mean reference radiance, over every pixel but those of the sun disk
// (whose radiance is a delta function the path tracer only samples).
#include "core/image_io.h"
#include "lab/scene.h"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace planet {

struct ChannelError {
  double rmse = 0;
  double mean_reference = 0;
  double relative() const { return mean_reference > 0 ? rmse / mean_reference : 0.0; }
};

struct TechniqueAccuracy {
  std::array<ChannelError, 3> channels{};
  int pixels = 0;  // compared, the sun disk left out
  // The same over the pixels whose ray misses the planet (open sky): the
  // ground's own shading (the frame's, not the technique's) left out.
  std::array<ChannelError, 3> sky_channels{};
  int sky_pixels = 0;
  // Per pixel and channel, (technique - reference) / mean reference.
  ImageRGB signed_error;
  double worst_relative() const;
};

// 1 for pixels whose centre lies within the sun's disk widened by a pixel
// and a half (a pixel that the disk covers in part); 0 elsewhere.
std::vector<uint8_t> sun_disk_mask(const Scene& scene);
// 1 for pixels whose ray meets the planet's bottom sphere.
std::vector<uint8_t> ground_mask(const Scene& scene);

TechniqueAccuracy measure_accuracy(const Scene& scene, const ImageRGB& technique,
                                   const ImageRGB& reference);

// RMS and mean per channel over the pixels the mask leaves in (mask 0):
// e.g. a reference's per-pixel standard error, and its radiance.
std::array<double, 3> masked_rms(const ImageRGB& image, const std::vector<uint8_t>& mask);
std::array<double, 3> masked_mean(const ImageRGB& image, const std::vector<uint8_t>& mask);

// Small images repeated pixel by pixel up to at least 256 columns, so that
// a 32x16 comparison can be looked at.
ImageRGB enlarged(const ImageRGB& image);
// Into `dir`: the technique, the reference and the error |t - r| / mean
// reference, each as EXR and as an enlarged tone-mapped PNG.
void write_accuracy_images(const std::filesystem::path& dir, const Scene& scene,
                           const ImageRGB& technique, const ImageRGB& reference,
                           const TechniqueAccuracy& accuracy);

}  // namespace planet
