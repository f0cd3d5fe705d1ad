#pragma once
// Heights from an image, read through OpenImageIO: an equirectangular map
// (longitude -180..180 degrees left to right, latitude 90..-90 top to
// bottom) whose first channel, times `scale` plus `offset`, is the height
// in metres. Sampled bilinearly; the error bound comes from the steepest
// step between neighbouring pixels.
#include "terrain/height_source.h"

#include <filesystem>
#include <vector>

namespace planet {

class HeightMap : public HeightSource {
 public:
  // Throws InputError naming the file when it cannot be read, is empty or
  // holds a value that is not finite.
  HeightMap(const std::filesystem::path& file, double scale, double offset);

  double height(const glm::dvec3& dir_body) const override;
  HeightRange range_near(const glm::dvec3& dir_body, double radius) const override;
  HeightRange range() const override { return range_; }
  double interpolation_error(double spacing) const override;

  int width() const { return width_; }
  int height_px() const { return height_; }

  // The body radius the map's pixel size is reckoned on (default: Earth).
  void set_body_radius(double radius) { body_radius_ = radius; }

 private:
  double texel(int x, int y) const;

  int width_ = 0, height_ = 0;
  std::vector<float> values_;
  HeightRange range_;
  double max_step_ = 0;  // largest height difference between neighbouring pixels
  double body_radius_ = 6371e3;
};

}  // namespace planet
