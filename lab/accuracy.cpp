#include "lab/accuracy.h"

#include "core/error.h"
#include "core/tone_map.h"
#include "lab/error_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace planet {

double TechniqueAccuracy::worst_relative() const {
  double worst = 0;
  for (const auto& c : channels) worst = std::max(worst, c.relative());
  return worst;
}

std::vector<uint8_t> sun_disk_mask(const Scene& scene) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  ReferenceView view = reference_view(scene, body, model);
  double pixel_angle = scene.camera.vertical_fov / double(scene.height);
  double cos_limit = std::cos(model.sun_angular_radius + 1.5 * pixel_angle);
  std::vector<uint8_t> mask(size_t(scene.width) * size_t(scene.height), 0);
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) {
      if (glm::dot(view.ray_dir(x, y), view.sun_dir_atmo) > cos_limit) {
        mask[size_t(y) * size_t(scene.width) + size_t(x)] = 1;
      }
    }
  }
  return mask;
}

std::vector<uint8_t> ground_mask(const Scene& scene) {
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  ReferenceView view = reference_view(scene, body, model);
  std::vector<uint8_t> mask(size_t(scene.width) * size_t(scene.height), 0);
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) {
      glm::dvec3 d = view.ray_dir(x, y), o = view.camera_atmo;
      double b = glm::dot(o, d);
      double closest = glm::length(o - b * d);
      if (b < 0 && closest < model.bottom_radius) {
        mask[size_t(y) * size_t(scene.width) + size_t(x)] = 1;
      }
    }
  }
  return mask;
}

namespace {

void check_sizes(const ImageRGB& a, const ImageRGB& b) {
  if (a.width != b.width || a.height != b.height) {
    throw InputError(fmt::format("images of {}x{} and {}x{} cannot be compared", a.width, a.height,
                                 b.width, b.height));
  }
}

}  // namespace

TechniqueAccuracy measure_accuracy(const Scene& scene, const ImageRGB& technique,
                                   const ImageRGB& reference) {
  check_sizes(technique, reference);
  std::vector<uint8_t> mask = sun_disk_mask(scene);
  std::vector<uint8_t> ground = ground_mask(scene);
  TechniqueAccuracy result;
  std::array<double, 3> sum_sq{}, sum_ref{}, sky_sq{}, sky_ref{};
  for (size_t i = 0; i < mask.size(); ++i) {
    if (mask[i]) continue;
    ++result.pixels;
    if (!ground[i]) ++result.sky_pixels;
    for (size_t c = 0; c < 3; ++c) {
      double t = technique.pixels[i * 3 + c], r = reference.pixels[i * 3 + c];
      sum_sq[c] += (t - r) * (t - r);
      sum_ref[c] += r;
      if (!ground[i]) {
        sky_sq[c] += (t - r) * (t - r);
        sky_ref[c] += r;
      }
    }
  }
  for (size_t c = 0; c < 3; ++c) {
    double n = std::max(result.pixels, 1), n_sky = std::max(result.sky_pixels, 1);
    result.channels[c] = {std::sqrt(sum_sq[c] / n), sum_ref[c] / n};
    result.sky_channels[c] = {std::sqrt(sky_sq[c] / n_sky), sky_ref[c] / n_sky};
  }
  result.signed_error = {technique.width, technique.height,
                         std::vector<float>(technique.pixels.size(), 0.0f)};
  for (size_t i = 0; i < mask.size(); ++i) {
    if (mask[i]) continue;
    for (size_t c = 0; c < 3; ++c) {
      double mean = result.channels[c].mean_reference;
      result.signed_error.pixels[i * 3 + c] =
          mean > 0 ? float((technique.pixels[i * 3 + c] - reference.pixels[i * 3 + c]) / mean)
                   : 0.0f;
    }
  }
  return result;
}

namespace {

// Sums of f(value) per channel over the pixels the mask leaves in, over
// their count.
template <class F>
std::array<double, 3> masked_average(const ImageRGB& image, const std::vector<uint8_t>& mask, F f) {
  std::array<double, 3> sum{};
  int n = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    if (mask[i]) continue;
    ++n;
    for (size_t c = 0; c < 3; ++c) sum[c] += f(double(image.pixels[i * 3 + c]));
  }
  for (auto& s : sum) s /= std::max(n, 1);
  return sum;
}

}  // namespace

std::array<double, 3> masked_rms(const ImageRGB& image, const std::vector<uint8_t>& mask) {
  std::array<double, 3> mean_square = masked_average(image, mask, [](double v) { return v * v; });
  for (auto& s : mean_square) s = std::sqrt(s);
  return mean_square;
}

std::array<double, 3> masked_mean(const ImageRGB& image, const std::vector<uint8_t>& mask) {
  return masked_average(image, mask, [](double v) { return v; });
}

// Small images repeated pixel by pixel up to at least 256 columns, so that
// a 32x16 comparison can be looked at.
ImageRGB enlarged(const ImageRGB& image) {
  int k = std::max(1, 256 / std::max(image.width, 1));
  ImageRGB out{image.width * k, image.height * k, {}};
  out.pixels.resize(size_t(out.width) * size_t(out.height) * 3);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        out.pixels[(size_t(y) * size_t(out.width) + size_t(x)) * 3 + size_t(c)] =
            image.pixels[(size_t(y / k) * size_t(image.width) + size_t(x / k)) * 3 + size_t(c)];
      }
    }
  }
  return out;
}

void write_accuracy_images(const std::filesystem::path& dir, const Scene& scene, const ImageRGB& technique,
                  const ImageRGB& reference, const TechniqueAccuracy& accuracy) {
  std::filesystem::create_directories(dir);
  write_exr(dir / (scene.name + "_technique.exr"), technique);
  write_tone_mapped_png(dir / (scene.name + "_technique.png"), enlarged(technique), scene.exposure);
  write_exr(dir / (scene.name + "_reference.exr"), reference);
  write_tone_mapped_png(dir / (scene.name + "_reference.png"), enlarged(reference), scene.exposure);
  // The error image: |technique - reference| / mean reference, shown so
  // that 10% of the mean is mid-grey-bright, with its scale below it.
  ImageRGB error = accuracy.signed_error;
  for (float& v : error.pixels) v = std::abs(v);
  write_exr(dir / (scene.name + "_error.exr"), error);
  write_error_png(dir / (scene.name + "_error.png"), error);
}

}  // namespace planet
