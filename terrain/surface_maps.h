#pragma once
// Imagery of a body's surface: a day image (the albedo seen from orbit) and
// a night image (the lights of its cities), both equirectangular
// (longitude -180..180 degrees left to right, geodetic latitude 90..-90
// top to bottom), read through OpenImageIO. From the day image comes a
// land mask (where its colour is open water), which shapes the procedural
// heights so that coastlines stay where the image draws them.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace planet {

struct SurfaceMapFiles {
  std::filesystem::path day;
  std::filesystem::path night;  // empty: no lights
  // Radiance of a white pixel of the night image after sRGB decoding,
  // W m^-2 sr^-1 nm^-1.
  double night_radiance = 2e-5;
  // Albedo of the day image's colours (surface_maps.cpp's day_albedo)
  // beyond this distance from the camera, metres; nearer, the palette's
  // colours of height and slope take over, which resolve what the
  // image's pixels (20 km on Earth) cannot.
  double fade_start_m = 20e3, fade_end_m = 120e3;
};

class SurfaceMaps {
 public:
  // Throws InputError naming the file when one is unreadable or not an
  // image. `flattening` turns a direction into geodetic latitude.
  SurfaceMaps(const SurfaceMapFiles& files, double flattening);

  const SurfaceMapFiles& files() const { return files_; }
  double flattening() const { return flattening_; }

  // The image's pixels, row 0 at the north: the day image as RGBA8, its
  // colour unchanged and alpha the blurred land mask (land()'s pixels);
  // the night image as RGBA8 (empty when there is none).
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<uint8_t>& day_rgba() const { return day_; }
  int night_width() const { return night_width_; }
  int night_height() const { return night_height_; }
  const std::vector<uint8_t>& night_rgba() const { return night_; }

  // How much of the ground along a direction is land, in [0, 1]: the
  // mask blurred over about two pixels, sampled bilinearly. 0 or 1
  // exactly wherever no coast lies within two pixels.
  double land(const glm::dvec3& dir_body) const;
  // The day image's colour along a direction, its display values in
  // [0, 1], sampled bilinearly as the shader samples it (its finest level).
  glm::dvec3 day_color(const glm::dvec3& dir_body) const;
  // A lower bound on the distance in metres from the direction to the
  // nearest point where land() is neither exactly 0 nor exactly 1.
  double distance_to_coast(const glm::dvec3& dir_body) const;
  // The largest change of land() per metre on the ground (away from the
  // poles, where the pixels narrow; a bound used for interpolation error).
  double max_land_slope() const { return max_land_slope_; }

  // Longitude in [-pi, pi] and geodetic latitude of a direction.
  glm::dvec2 lon_lat(const glm::dvec3& dir_body) const;

 private:
  // The pixel (x, y) of a map, wrapped in longitude, clamped in latitude,
  // as an index into its row-major pixels.
  size_t pixel_index(int x, int y) const;
  double texel(const std::vector<float>& a, int x, int y) const;
  // The bilinear blend of texel(x, y) around a direction (pixel centres
  // at (i + 0.5) / width of the longitude span).
  template <class Texel>
  auto bilinear(const glm::dvec3& dir_body, Texel texel) const;

  SurfaceMapFiles files_;
  double flattening_ = 0;
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> day_;
  int night_width_ = 0, night_height_ = 0;
  std::vector<uint8_t> night_;
  std::vector<float> land_;      // blurred mask
  std::vector<float> coast_px_;  // distance in pixels to a pixel that is neither 0 nor 1
  double pixel_m_ = 0;           // a pixel's height in metres on the ground
  double max_land_slope_ = 0;
};

// Whether a colour of the day image is open water: deep blue, darker than
// any ice or cloud.
bool is_open_water(uint8_t r, uint8_t g, uint8_t b);

}  // namespace planet
