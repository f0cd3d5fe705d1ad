#pragma once
// Heights from a global elevation grid (ETOPO, MOLA MEGDR, LOLA LDEM): a
// regular latitude-longitude grid of 16-bit samples read in its source's
// own layout, interpolated by bicubic Catmull-Rom (C1: the ground's slope
// has no kinks at the samples' rows and columns), wrapping in longitude and
// continuing across each pole onto the meridian opposite, with one value at
// each pole (the mean of the nearest ring of samples) into which the
// surface blends within the first row.
#include "terrain/height_source.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct GridSpec {
  enum class Layout { kInt16Le, kInt16Be, kPngU16 };
  // kPixel: sample (i, j) is the mean over a cell, its centre (i + 0.5)
  // cells from the grid's west and north edges (PDS products); kNode: the
  // value at a point i cells east of the west edge, j rows south of the
  // north pole, with rows on both poles (ETOPO).
  enum class Registration { kPixel, kNode };
  std::filesystem::path file;
  Layout layout = Layout::kInt16Le;
  Registration registration = Registration::kPixel;
  int width = 0, height = 0;
  double west_longitude_deg = 0;  // the west edge (kPixel) or column 0 (kNode)
  double scale = 1, offset = 0;   // metres = sample * scale + offset
  // Rows by the latitude of the ellipsoid's normal (Earth's grids) rather
  // than of the direction from the centre (MOLA's, LOLA's planetocentric).
  bool geodetic_latitude = false;
};

// The heights a grid may hold: no relief in the solar system reaches
// 30 km from its datum (Olympus Mons 21.9 km, Rheasilvia's peak on Vesta
// 22 km), and a 16-bit grid's missing-data value (-32768) lies beyond.
constexpr double kMaxGridHeight = 30000.0;

// The grid's samples and what is known of them before any lookup.
class GridData {
 public:
  // Throws InputError naming the file when it is missing, unreadable, not
  // of the declared size or layout, or holds a height that is not finite
  // or beyond kMaxGridHeight.
  explicit GridData(const GridSpec& spec);

  const GridSpec& spec() const { return spec_; }
  // The sample (column i, row j) in metres: i wraps; j beyond a pole
  // continues on the meridian opposite.
  double sample(int i, int j) const;
  // Bytes the samples and their min-max pyramid hold.
  size_t memory_bytes() const;

 private:
  friend class GridHeight;
  void read_raw();
  void read_png();
  void check_and_summarise();
  // Min and max of the samples in rows j0..j1, columns i0..i1 (i may run
  // past the grid's width: it wraps), conservatively (whole blocks).
  HeightRange sample_range(int i0, int i1, int j0, int j1) const;

  GridSpec spec_;
  std::vector<int16_t> codes_;  // row-major, north row first
  double scale_ = 1, offset_ = 0;
  // kBlock x kBlock blocks' minimum and maximum, then blocks of those, ...
  static constexpr int kBlock = 4;
  struct Level {
    int width = 0, height = 0;
    std::vector<float> min, max;
  };
  std::vector<Level> levels_;
  HeightRange range_;
  double pole_[2] = {0, 0};  // north, south: the nearest ring's mean
  double max_step_ = 0;      // largest difference between neighbouring samples
  double max_slope_ = 0;     // largest such difference per metre, on the unit sphere
};

class GridHeight : public HeightSource {
 public:
  // `radius`: the body's mean radius; `ellipsoid_ratio2`: (a / b)^2 of the
  // body's ellipsoid, for geodetic rows; `sea_level`: heights below it are
  // raised to it (a calm sea over the grid's sea floor), or none.
  GridHeight(std::shared_ptr<const GridData> data, double radius, double ellipsoid_ratio2,
             std::optional<double> sea_level);

  double height(const glm::dvec3& dir_body) const override;
  double seabed_height(const glm::dvec3& dir_body) const override;
  HeightRange range_near(const glm::dvec3& dir_body, double radius) const override;
  HeightRange range() const override { return range_; }
  double interpolation_error(double spacing) const override;

  const GridData& data() const { return *data_; }
  // The grid's value nearest a direction (no interpolation): what a person
  // reads off the grid at a place.
  double nearest_sample(const glm::dvec3& dir_body) const;

  // The direction's position in sample units: u east from column 0's
  // centre, v south from row 0's (samples stand at whole u and v).
  void grid_coordinates(const glm::dvec3& dir_body, double& u, double& v) const;
  // The latitude, radians, of the row at v (geodetic for geodetic rows).
  double row_latitude(double v) const;
  // Rows per radian of latitude.
  double rows_per_radian() const;
  // The heights of the interpolated grid within `radius` of the direction,
  // as range_near() without the sea: the floor under it.
  HeightRange seabed_range_near(const glm::dvec3& dir_body, double radius) const;

 protected:
  HeightRange padded(HeightRange samples) const;

  std::shared_ptr<const GridData> data_;
  double radius_;
  double ellipsoid_ratio2_;
  std::optional<double> sea_level_;
  HeightRange range_;
};

}  // namespace planet
