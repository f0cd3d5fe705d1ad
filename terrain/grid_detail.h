#pragma once
// Detail below an elevation grid's resolution: relief noise whose
// amplitude and roughness follow the grid's local relief, and on cratered
// bodies craters below the grid's cell size by the body's size-frequency
// law, added to the grid's own interpolation (grid_height.h) so that the
// data stays where it is:
// - over each of the grid's cells (the pixel a sample stands for, or the
//   square between four nodes) the detail averages to zero, and at every
//   sample it is zero: the relief noise by its construction (the
//   divergence of a vector noise that vanishes across the cells' edges,
//   see grid_detail.cpp), the craters by holding no volume and being kept
//   only where they lie within one cell and off its sample;
// - near a sea it never lifts the floor above it nor sinks land below it;
// - it fades out toward the poles (poleward of 66 degrees of latitude to
//   none past 78), where the grid's cells narrow to slivers.
// docs/bodies.md, "Detail below the data", has the long story.
#include "terrain/grid_height.h"

#include <cstdint>

namespace planet {

struct GridDetailSpec {
  // The relief noise: the first octave's amplitude (its wavelength half a
  // cell) is relief_ratio times the local relief (the span of the 3 x 3
  // samples about a node), within [min_amplitude_m, max_amplitude_m];
  // each finer octave's is `gain` times the one before, gain_smooth where
  // the relief is nil to gain_rough from rough_relief_m on.
  double relief_ratio = 0.2;
  double min_amplitude_m = 2.0;
  double max_amplitude_m = 400.0;
  double rough_relief_m = 1500.0;
  double gain_smooth = 0.4, gain_rough = 0.5;
  double sea_floor = 0.1;  // the amplitude's factor where the sample lies under the sea
  int octaves = 8;
  uint32_t seed = 1;
  // Craters: none where crater_octaves is 0. The largest craters' lattice
  // is the grid's cell (radii 0.1 to 0.25 of it), each next octave's half
  // the last's; the cumulative number of craters wider than D goes as
  // D^-crater_sfd_exponent (2: each octave's cells hold craters with the
  // same chance, crater_density).
  int crater_octaves = 0;
  double crater_depth_ratio = 0.4;  // rim crest over floor, per radius
  double crater_density = 0.5;
  double crater_sfd_exponent = 2.0;
  uint32_t crater_seed = 2;
};

class GridDetail : public GridHeight {
 public:
  GridDetail(std::shared_ptr<const GridData> data, double radius, double ellipsoid_ratio2,
             std::optional<double> sea_level, const GridDetailSpec& spec);

  double height(const glm::dvec3& dir_body) const override;
  double seabed_height(const glm::dvec3& dir_body) const override;
  HeightRange range_near(const glm::dvec3& dir_body, double radius) const override;
  HeightRange range() const override { return detail_range_; }
  double interpolation_error(double spacing) const override;
  CraterMarks crater_marks(const glm::dvec3& dir_body, double spacing) const override;

  const GridDetailSpec& spec() const { return spec_; }
  // The detail alone at a direction (the seabed's height less the grid's),
  // before the sea's limit: what averages to zero over each cell.
  double detail(const glm::dvec3& dir_body) const;
  // The grid's cells' edges stand at u and v of edge_offset() + whole numbers.
  double edge_offset() const { return edge_offset_; }

 private:
  double relief_detail(double u, double v) const;
  double crater_detail(const glm::dvec3& dir_body) const;
  // Whether the crater centred at c (in cells of `cell` metres), of
  // radius r cells, is laid: within one grid cell, off its sample, and
  // kept by the polar fade (its draws go on from s).
  bool crater_kept(const glm::dvec3& c, double r, double cell, uint32_t s) const;
  // Bounds of the relief noise's height and slope for a first octave's
  // amplitude a0 and gain, and of the craters'.
  double relief_bound(double a0, double gain) const;
  double crater_bound() const;
  // The largest amplitude and gain a cap of local relief `relief` may hold.
  double amplitude_for(double relief) const;
  double gain_for(double relief) const;

  GridDetailSpec spec_;
  double edge_offset_;         // 0.5 (pixel cells) or 0 (node cells)
  double metres_per_row_;      // along a meridian
  double metres_per_column_;   // along the equator
  double taper_over_cos_ = 1;  // the largest polar fade over cos(latitude) next to a row
  double crater_cell_ = 0;     // metres: the largest craters' lattice
  HeightRange detail_range_;
};

}  // namespace planet
