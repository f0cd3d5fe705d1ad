#include "terrain/height_map.h"

#include "core/error.h"
#include "core/image_io.h"
#include "core/paths.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

HeightMap::HeightMap(const std::filesystem::path& file, double scale, double offset) {
  check_readable_file(file);
  check_image_signature(file, "a height map");
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) {
    throw InputError(
        fmt::format("{}: cannot read height map: {}", file.string(), OIIO::geterror()));
  }
  const OIIO::ImageSpec& spec = in->spec();
  check_image_size(file, "a height map", spec.width, spec.height, spec.nchannels);
  width_ = spec.width;
  height_ = spec.height;
  if (width_ < 2 || height_ < 2 || spec.nchannels < 1) {
    throw InputError(fmt::format("{}: height map is empty ({}x{} pixels, {} channels)",
                                 file.string(), width_, height_, spec.nchannels));
  }
  std::vector<float> all(size_t(width_) * size_t(height_) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data())) {
    throw InputError(
        fmt::format("{}: cannot read height map pixels: {}", file.string(), in->geterror()));
  }
  values_.resize(size_t(width_) * size_t(height_));
  range_ = {1e300, -1e300};
  for (size_t i = 0; i < values_.size(); ++i) {
    double v = double(all[i * size_t(spec.nchannels)]) * scale + offset;
    if (!std::isfinite(v)) {
      throw InputError(fmt::format("{}: height map pixel ({}, {}) is not a number", file.string(),
                                   i % size_t(width_), i / size_t(width_)));
    }
    values_[i] = float(v);
    range_.min = std::min(range_.min, v);
    range_.max = std::max(range_.max, v);
  }
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      double v = texel(x, y);
      max_step_ = std::max({max_step_, std::abs(texel(x + 1, y) - v),
                            std::abs(texel(x, std::min(y + 1, height_ - 1)) - v)});
    }
  }
}

double HeightMap::texel(int x, int y) const {
  x = ((x % width_) + width_) % width_;  // longitude wraps
  y = std::clamp(y, 0, height_ - 1);
  return values_[size_t(y) * size_t(width_) + size_t(x)];
}

double HeightMap::height(const glm::dvec3& d) const {
  double lon = std::atan2(d.y, d.x);
  double lat = std::asin(std::clamp(d.z, -1.0, 1.0));
  // Pixel centres at (i + 0.5) / width of the longitude span.
  double u = (lon / (2.0 * glm::pi<double>()) + 0.5) * width_ - 0.5;
  double v = (0.5 - lat / glm::pi<double>()) * height_ - 0.5;
  double fu = std::floor(u), fv = std::floor(v);
  int x = int(fu), y = int(fv);
  double a = u - fu, b = v - fv;
  return (1 - b) * ((1 - a) * texel(x, y) + a * texel(x + 1, y)) +
         b * ((1 - a) * texel(x, y + 1) + a * texel(x + 1, y + 1));
}

HeightRange HeightMap::range_near(const glm::dvec3& dir_body, double radius) const {
  // Bilinear interpolation moves at most max_step per pixel of distance;
  // a pixel is narrowest (in metres) along the latitude rows near the poles,
  // so this stays a loose but safe bound only away from them.
  double pixel = glm::pi<double>() * body_radius_ / height_;
  double spread = max_step_ * (radius / pixel + 1.0);
  double h = height(dir_body);
  return {std::max(h - spread, range_.min), std::min(h + spread, range_.max)};
}

double HeightMap::interpolation_error(double spacing) const {
  double pixel = glm::pi<double>() * body_radius_ / height_;
  return std::min(range_.max - range_.min, max_step_ * (spacing / pixel + 1.0) / 2.0);
}

}  // namespace planet
