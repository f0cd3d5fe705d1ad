#pragma once
// Heights of a body shaped like its control cage: the Catmull-Clark limit
// surface (Catmull and Clark 1978) of a closed OBJ cage, evaluated with
// OpenSubdiv, scaled so that its mean radius is the body's radius, and
// displaced by noise layers as in ProceduralHeight. A measured shape model
// (433 Eros) instead keeps its own frame and size: given the metres per
// unit of its file, the cage is neither moved nor scaled, so that its
// origin (the body's centre of mass) and axes (the pole, the prime
// meridian) stay those of the body's rotation.
//
// The limit surface is assumed star-shaped about the centroid of its limit
// points (about the origin, for a model in its own frame): height is a
// function of direction. Where a ray from the centre
// meets the surface more than once (an overhang), the outermost crossing
// counts; a cage whose centre lies outside its own surface is rejected.
//
// Evaluation: the cage is refined uniformly until it has 5 x 10^4 faces or more,
// and the exact limit position of every refined vertex is taken (limit
// masks, Halstead et al. 1993). Rays from the centre through a cube map of
// 129 x 129 directions per face are intersected with that mesh of limit
// points once, at construction; height() interpolates that table
// bilinearly, and the bounds below say how far the table can stray from the
// limit surface.
#include "terrain/height_source.h"
#include "terrain/obj_cage.h"
#include "terrain/procedural_height.h"

#include <optional>
#include <string>
#include <vector>

namespace planet {

// The limit positions of the vertices of the cage refined `level` times
// (level >= 1), in the cage's own coordinates. Throws InputError naming
// `name` when OpenSubdiv rejects the topology.
std::vector<glm::dvec3> cage_limit_points(const ObjCage& cage, int level, const std::string& name);

class CageHeight : public HeightSource {
 public:
  static constexpr int kTableCells = 128;  // table cells per cube face edge

  // `name` (the file) is for messages; `body_radius` is the radius
  // heights are measured from, and the one the cage's mean radius is scaled
  // to unless `units_m` (metres per cage unit) keeps the cage's own origin
  // and size.
  CageHeight(const ObjCage& cage, const std::string& name, double body_radius,
             std::vector<NoiseLayer> layers, std::optional<double> units_m = std::nullopt);

  double height(const glm::dvec3& dir_body) const override;
  HeightRange range_near(const glm::dvec3& dir_body, double radius) const override;
  HeightRange range() const override { return range_; }
  double interpolation_error(double spacing) const override;
  CraterMarks crater_marks(const glm::dvec3& dir_body, double spacing) const override {
    return noise_.crater_marks(dir_body, spacing);
  }

  // The radius of the (scaled) limit surface along a unit direction, from
  // the table, without noise.
  double surface_radius(const glm::dvec3& dir_body) const;
  // A bound on |surface_radius - the limit surface's radius|, metres.
  double table_error() const { return table_error_; }
  // The refined mesh's limit points, scaled and relative to the centre (the
  // origin, for a cage in its own frame): the
  // direct evaluation the table is checked against.
  const std::vector<glm::dvec3>& limit_points() const { return limit_points_; }
  // Metres per cage unit.
  double scale() const { return scale_; }

 private:
  double measure_table();
  double& cell(int face, int i, int j) {
    return table_[size_t((face * (kTableCells + 1) + j) * (kTableCells + 1) + i)];
  }
  double cell(int face, int i, int j) const {
    return table_[size_t((face * (kTableCells + 1) + j) * (kTableCells + 1) + i)];
  }

  double body_radius_;
  double scale_ = 1;
  std::vector<double> table_;  // radius, metres, at each cube-map grid point
  std::vector<glm::dvec3> limit_points_;
  double table_error_ = 0;
  double min_radius_ = 0, max_radius_ = 0;
  double max_slope_ = 0;      // largest |dr / d angle| between grid neighbours, metres per radian
  double max_curvature_ = 0;  // largest |d2r / d angle2|, metres per radian^2
  ProceduralHeight noise_;
  HeightRange range_;
};

}  // namespace planet
