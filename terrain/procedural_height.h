#pragma once
// Procedural heights: a sum of layers of gradient noise (fBm, ridged) and
// crater fields, each with its amplitude and wavelength from the body's
// file, evaluated on the sphere of the body's mean radius so that features
// keep their size in metres whatever the direction.
#include "terrain/height_source.h"

#include <cstdint>
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

  std::optional<double> sea_level() const { return sea_level_; }

 private:
  double raw_height(const glm::dvec3& p) const;

  double radius_;
  std::vector<NoiseLayer> layers_;
  double offset_;
  std::optional<double> sea_level_;
  HeightRange range_;
};

}  // namespace planet
