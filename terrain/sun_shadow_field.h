#pragma once
// The terrain's shadow in the air: over a square patch of ground around the
// camera, the altitude below which the terrain hides the sun (a
// shadow-height field). A point of the air above a cell is in the terrain's
// shadow when its altitude lies below the cell's shadow height, so the
// atmosphere's marches test a point with one texture read: light shafts at
// sunset over ridges, shadowed haze in craters.
//
// Everything is in atmosphere space (the body frame scaled so that the
// ellipsoid becomes the atmosphere's bottom sphere, atmosphere_space.h),
// where the marches work: altitudes are above the bottom sphere. The patch
// is a gnomonic grid about its centre direction `up`: a direction q lies at
// (x, y) = R (q.east, q.north) / (q.up), and cell (i, j) of n holds the
// direction at x = (i + 0.5 - n / 2) * cell, likewise y with j.
//
// Each cell marches toward the sun from its ground point, over the patch's
// ground heights: the shadow height is the highest of (ground height - the
// sun ray's rise to there) along the way, and never below the cell's own
// ground. The centre snaps to a lattice of an eighth of the patch and the
// sun to steps of 1e-4 in the patch's frame, so that the field is a pure
// function of the frame's camera and sun (captures stay byte-identical
// across slices) and a camera or sun that hardly moves reuses it.
#include "terrain/terrain_surface.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace planet {

struct ShadowPatch {
  glm::dvec3 up{0, 0, 1}, east{1, 0, 0}, north{0, 1, 0};
  double bottom_radius = 0;  // R of the gnomonic map
  double half_side = 0;      // metres from the centre to an edge, on the plane
  int size = 0;              // cells along each side
  double cell() const { return 2.0 * half_side / size; }
  // The direction's place on the plane; false behind the patch's horizon.
  bool plane(const glm::dvec3& q, double& x, double& y) const;
};

class SunShadowField {
 public:
  explicit SunShadowField(int size = 160, double half_side = 40e3);

  // The field for a camera and a sun (unit, atmosphere space) over
  // `surface` seen through atmosphere space's `atmo_scale` and bottom
  // radius. True when the shadow heights changed since the last call.
  bool update(const TerrainSurface& surface, const glm::dvec3& atmo_scale, double bottom_radius,
              const glm::dvec3& camera_atmo, const glm::dvec3& sun_atmo);

  const ShadowPatch& patch() const { return patch_; }
  // Per cell, row by row (j * size + i): the ground's altitude, and the
  // altitude below which the terrain hides the sun.
  const std::vector<float>& ground() const { return ground_; }
  const std::vector<float>& shadow() const { return shadow_; }
  // Bilinear between cell centres, clamped at the patch's edge.
  double shadow_height(double x, double y) const;
  // The highest shadow height of a cell that lies in shadow (above its
  // ground by more than a metre); -infinity when none does.
  double highest_shadow() const { return highest_; }
  // Counts the changes of the shadow heights.
  uint64_t version() const { return version_; }

 private:
  double ground_at(double x, double y) const;
  void compute_shadow(const glm::dvec3& sun);

  int size_;
  double half_side_;
  ShadowPatch patch_;
  glm::dvec3 centre_{0.0}, sun_{0.0};
  const TerrainSurface* surface_ = nullptr;
  glm::dvec3 scale_{0.0};
  float ground_max_ = 0;
  double highest_ = 0;
  std::vector<float> ground_, shadow_;
  uint64_t version_ = 0;
};

}  // namespace planet
