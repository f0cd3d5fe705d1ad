#pragma once
// Procedural heights: a sum of layers of gradient noise (fBm, ridged) and
// crater fields, each with its amplitude and wavelength from the body's
// file, evaluated on the sphere of the body's mean radius so that features
// keep their size in metres whatever the direction.
#include "terrain/height_source.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct NoiseLayer {
  enum class Kind { kFbm, kRidged, kCraters };
  Kind kind = Kind::kFbm;
  double amplitude = 1000;    // metres: the first octave's half range (crater depth for craters)
  double wavelength = 1e5;    // metres: the first octave's feature size (crater cell size)
  int octaves = 8;
  double gain = 0.5;          // amplitude ratio between octaves
  double lacunarity = 2.0;    // frequency ratio between octaves
  double density = 0.5;       // craters: chance that a cell holds one
  uint32_t seed = 1;
};

class SurfaceMaps;

class ProceduralHeight : public HeightSource {
 public:
  // `radius`: the body's mean radius; `sea_level`: heights below it are
  // raised to it (a calm ocean), or none.
  ProceduralHeight(double radius, std::vector<NoiseLayer> layers, double offset,
                   std::optional<double> sea_level);

  double height(const glm::dvec3& dir_body) const override;
  HeightRange range_near(const glm::dvec3& dir_body, double radius) const override;
  HeightRange range() const override { return range_; }
  double interpolation_error(double spacing) const override;
  CraterMarks crater_marks(const glm::dvec3& dir_body, double spacing) const override;
  double seabed_height(const glm::dvec3& dir_body) const override;

  std::optional<double> sea_level() const { return sea_level_; }

  // Coastlines from a map's land mask (needs a sea level): where the map
  // is land, ground the noise put below kLandAbove over the sea rises to
  // it; where it is water, ground above kSeaBelow under it sinks to it;
  // across a coast (a few of the map's pixels) the two blend, so that the
  // coastline follows the map's, roughened by the noise. Far from any
  // coast, ground the noise put well above the sea on land is unchanged.
  void set_land_mask(std::shared_ptr<const SurfaceMaps> maps);
  static constexpr double kLandAbove = 30.0;   // metres over the sea
  static constexpr double kSeaBelow = 200.0;   // metres under it
  static constexpr double kSoftening = 50.0;   // metres over which each bend rounds

 private:
  double raw_height(const glm::dvec3& p) const;
  // The land mask's reshaping of a noise height h, where the map says
  // `land` (in [0, 1]).
  double shaped(double h, double land) const;
  HeightRange shaped_range(HeightRange r, double land_min, double land_max) const;
  double land_mask_error(double spacing) const;

  double radius_;
  std::vector<NoiseLayer> layers_;
  double offset_;
  std::optional<double> sea_level_;
  HeightRange raw_range_;  // the noise's, before the sea and the land mask
  HeightRange range_;
  std::shared_ptr<const SurfaceMaps> maps_;
};

}  // namespace planet
