#include "terrain/surface_maps.h"

#include "terrain/jpeg_image.h"

#include "core/error.h"
#include "core/image_io.h"
#include "core/paths.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

// Earth's mean radius: the images' pixel size on the ground is reckoned
// on it (the maps are Earth's; another body's would scale its own).
constexpr double kMapBodyRadius = 6371e3;
// The land mask's blur: a box of this many pixels each side of the
// centre, twice over: a tent five pixels wide, reaching two each way.
constexpr int kBlur = 1;

struct Rgba8 {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

void check_equirectangular(const std::filesystem::path& file, const char* what, int width,
                           int height) {
  if (width < 4 || height < 2 || width != 2 * height) {
    throw InputError(
        fmt::format("{}: {} must be equirectangular, twice as wide as high (it is {}x{} pixels)",
                    file.string(), what, width, height));
  }
}

Rgba8 read_rgba8(const std::filesystem::path& file, const char* what) {
  check_readable_file(file);
  if (looks_like_jpeg(file)) {
    JpegImage jpeg = read_jpeg_rgba(file, what);
    check_equirectangular(file, what, jpeg.width, jpeg.height);
    return {jpeg.width, jpeg.height, std::move(jpeg.rgba)};
  }
  check_image_signature(file, what);
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) {
    throw InputError(fmt::format("{}: cannot read {}: {}", file.string(), what, OIIO::geterror()));
  }
  const OIIO::ImageSpec& spec = in->spec();
  check_image_size(file, what, spec.width, spec.height, spec.nchannels);
  check_equirectangular(file, what, spec.width, spec.height);
  const int n = spec.nchannels;
  std::vector<uint8_t> all(size_t(spec.width) * size_t(spec.height) * size_t(n));
  if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::UINT8, all.data())) {
    throw InputError(
        fmt::format("{}: cannot read the pixels of {}: {}", file.string(), what, in->geterror()));
  }
  Rgba8 out{spec.width, spec.height, {}};
  out.rgba.resize(size_t(spec.width) * size_t(spec.height) * 4);
  for (size_t i = 0; i < size_t(spec.width) * size_t(spec.height); ++i) {
    for (int c = 0; c < 3; ++c)
      out.rgba[i * 4 + size_t(c)] = all[i * size_t(n) + size_t(std::min(c, n - 1))];
    out.rgba[i * 4 + 3] = 255;
  }
  return out;
}

// A box blur along rows (longitude wraps) then along columns (clamped at
// the poles), `r` pixels each side.
std::vector<float> box_blur(const std::vector<float>& a, int w, int h, int r) {
  std::vector<float> rows(a.size()), out(a.size());
  const float n = float(2 * r + 1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float s = 0;
      for (int k = -r; k <= r; ++k) s += a[size_t(y) * size_t(w) + size_t((x + k + w) % w)];
      rows[size_t(y) * size_t(w) + size_t(x)] = s / n;
    }
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float s = 0;
      for (int k = -r; k <= r; ++k) {
        s += rows[size_t(std::clamp(y + k, 0, h - 1)) * size_t(w) + size_t(x)];
      }
      out[size_t(y) * size_t(w) + size_t(x)] = s / n;
    }
  }
  return out;
}

}  // namespace

bool is_open_water(uint8_t r, uint8_t g, uint8_t b) { return b > 1.15 * r && b >= g && b < 153; }

SurfaceMaps::SurfaceMaps(const SurfaceMapFiles& files, double flattening)
    : files_(files), flattening_(flattening) {
  Rgba8 day = read_rgba8(files.day, "a day image");
  width_ = day.width;
  height_ = day.height;
  day_ = std::move(day.rgba);
  if (!files.night.empty()) {
    Rgba8 night = read_rgba8(files.night, "a night image");
    night_width_ = night.width;
    night_height_ = night.height;
    night_ = std::move(night.rgba);
  }

  const size_t count = size_t(width_) * size_t(height_);
  std::vector<float> mask(count);
  for (size_t i = 0; i < count; ++i) {
    bool water = is_open_water(day_[i * 4], day_[i * 4 + 1], day_[i * 4 + 2]);
    mask[i] = water ? 0.0f : 1.0f;
  }
  land_ = box_blur(box_blur(mask, width_, height_, kBlur), width_, height_, kBlur);
  // The shader reads the blurred mask, as the heights do, so that the
  // image's colours turn from water to land where the ground does.
  for (size_t i = 0; i < count; ++i) day_[i * 4 + 3] = uint8_t(std::lround(land_[i] * 255.0f));
  // Sums of ninths can miss 0 and 1 by a rounding: a pixel whose whole
  // neighbourhood agrees is exactly that.
  for (float& v : land_) {
    if (v < 1e-6f) v = 0.0f;
    if (v > 1.0f - 1e-6f) v = 1.0f;
  }

  // Distance to the nearest pixel that is neither 0 nor 1: two chamfer
  // passes (steps 1 and sqrt 2), each run twice so that the distance
  // carries across the wrap in longitude.
  constexpr float kFar = 1e9f;
  coast_px_.assign(count, kFar);
  for (size_t i = 0; i < count; ++i) {
    if (land_[i] > 0.0f && land_[i] < 1.0f) coast_px_[i] = 0.0f;
  }
  auto at = [&](int x, int y) -> float& {
    return coast_px_[size_t(y) * size_t(width_) + size_t((x + width_) % width_)];
  };
  const float diag = std::sqrt(2.0f);
  for (int round = 0; round < 2; ++round) {
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        float& d = at(x, y);
        d = std::min(d, at(x - 1, y) + 1.0f);
        if (y > 0) {
          d = std::min({d, at(x, y - 1) + 1.0f, at(x - 1, y - 1) + diag, at(x + 1, y - 1) + diag});
        }
      }
    }
    for (int y = height_ - 1; y >= 0; --y) {
      for (int x = width_ - 1; x >= 0; --x) {
        float& d = at(x, y);
        d = std::min(d, at(x + 1, y) + 1.0f);
        if (y < height_ - 1) {
          d = std::min({d, at(x, y + 1) + 1.0f, at(x - 1, y + 1) + diag, at(x + 1, y + 1) + diag});
        }
      }
    }
  }

  pixel_m_ = glm::pi<double>() * kMapBodyRadius / height_;
  // The steepest step of the blurred mask between neighbours, per metre;
  // along a row the pixels narrow as cos(latitude), here taken no
  // narrower than at 80 degrees (a bound for the tiles' skirts, not for
  // correctness of any image).
  double steepest = 0;
  for (int y = 0; y < height_; ++y) {
    double lat = (0.5 - (y + 0.5) / height_) * glm::pi<double>();
    double row_m = pixel_m_ * std::max(std::cos(lat), std::cos(glm::radians(80.0)));
    for (int x = 0; x < width_; ++x) {
      double v = texel(land_, x, y);
      steepest = std::max(steepest, std::abs(texel(land_, x + 1, y) - v) / row_m);
      if (y + 1 < height_) {
        steepest = std::max(steepest, std::abs(texel(land_, x, y + 1) - v) / pixel_m_);
      }
    }
  }
  max_land_slope_ = steepest;
}

size_t SurfaceMaps::pixel_index(int x, int y) const {
  x = ((x % width_) + width_) % width_;
  y = std::clamp(y, 0, height_ - 1);
  return size_t(y) * size_t(width_) + size_t(x);
}

double SurfaceMaps::texel(const std::vector<float>& a, int x, int y) const {
  return a[pixel_index(x, y)];
}

glm::dvec2 SurfaceMaps::lon_lat(const glm::dvec3& d) const {
  // On an ellipsoid of flattening f, tan(geodetic) = tan(geocentric) / (1 - f)^2.
  double k = (1.0 - flattening_) * (1.0 - flattening_);
  return {std::atan2(d.y, d.x), std::atan2(d.z, k * std::hypot(d.x, d.y))};
}

template <class Texel>
auto SurfaceMaps::bilinear(const glm::dvec3& dir_body, Texel texel) const {
  glm::dvec2 ll = lon_lat(dir_body);
  double u = (ll.x / (2.0 * glm::pi<double>()) + 0.5) * width_ - 0.5;
  double v = (0.5 - ll.y / glm::pi<double>()) * height_ - 0.5;
  double fu = std::floor(u), fv = std::floor(v);
  int x = int(fu), y = int(fv);
  double a = u - fu, b = v - fv;
  return (1 - b) * ((1 - a) * texel(x, y) + a * texel(x + 1, y)) +
         b * ((1 - a) * texel(x, y + 1) + a * texel(x + 1, y + 1));
}

double SurfaceMaps::land(const glm::dvec3& dir_body) const {
  return bilinear(dir_body, [&](int x, int y) { return texel(land_, x, y); });
}

glm::dvec3 SurfaceMaps::day_color(const glm::dvec3& dir_body) const {
  return bilinear(dir_body, [&](int x, int y) {
    const uint8_t* p = &day_[pixel_index(x, y) * 4];
    return glm::dvec3(p[0], p[1], p[2]) / 255.0;
  });
}

double SurfaceMaps::distance_to_coast(const glm::dvec3& dir_body) const {
  glm::dvec2 ll = lon_lat(dir_body);
  int x = int(std::floor((ll.x / (2.0 * glm::pi<double>()) + 0.5) * width_));
  int y = int(std::floor((0.5 - ll.y / glm::pi<double>()) * height_));
  // The bilinear sample reaches one pixel from the nearest centre; the
  // pixels narrow toward the poles as cos(latitude), reckoned at the most
  // poleward latitude the distance can reach.
  // The chamfer's steps (1 and sqrt 2) overstate a distance by at most 8.3 %.
  double px = std::max(texel(coast_px_, x, y) / 1.083 - 1.5, 0.0);
  double reach =
      std::min(std::abs(ll.y) + px * glm::pi<double>() / height_, glm::half_pi<double>());
  return px * pixel_m_ * std::cos(reach);
}

}  // namespace planet
