#include "terrain/terrain_surface.h"

#include "terrain/cube_sphere.h"
#include "terrain/horizon.h"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>

namespace planet {

std::string TileKey::name() const { return fmt::format("{}/{}/{}/{}", face, level, x, y); }

TerrainSurface::TerrainSurface(const Ellipsoid& shape, TerrainConfig config)
    : shape_(shape), config_(std::move(config)), horizon_memo_(std::make_shared<HorizonMemo>()) {
  // The tangent warp makes a face's cells nearly equal: the largest is
  // 1.19 times the mean in length (1.41 in area), and a face edge spans a
  // quarter of the equator.
  double a = shape_.equatorial_radius, b = shape_.polar_radius();
  double face_edge = 0.5 * glm::pi<double>() * a;
  // The ellipsoid is most curved at the equator along the meridian: b^2 / a.
  double min_curvature_radius = b * b / a;
  for (int level = 0; level <= 24; ++level) {
    double spacing = 1.19 * face_edge / double(kTileGrid - 1) / double(1u << level);
    spacing_.push_back(spacing);
    // A triangle's longest edge is the cell diagonal; the ellipsoid sags
    // d^2 / (8 rho) below the chord of length d.
    double d = spacing * glm::root_two<double>();
    error_.push_back(heights().interpolation_error(d) + d * d / (8.0 * min_curvature_radius));
  }
}

glm::dvec3 TerrainSurface::point(const glm::dvec3& dir, double* height) const {
  double h = heights().height(dir);
  if (height) *height = h;
  return point_at_height(dir, h);
}

glm::dvec3 TerrainSurface::point_at_height(const glm::dvec3& dir, double height) const {
  glm::dvec3 p = ellipsoid_point(shape_, dir);
  return p + height * ellipsoid_normal(shape_, p);
}

glm::dvec3 TerrainSurface::face_point(int face, double s, double t, double* height) const {
  return point(cube_to_sphere(face, s, t), height);
}

TileBounds TerrainSurface::bounds(const TileKey& key, const HeightRange* heights_known) const {
  TileBounds b;
  double s0 = key.s0(), t0 = key.t0(), size = key.size();
  glm::dvec3 mid_dir = cube_to_sphere(key.face, s0 + 0.5 * size, t0 + 0.5 * size);
  b.center_body = ellipsoid_point(shape_, mid_dir);
  // The tile's ground lies within a cap around mid_dir whose surface
  // radius is at most half the diagonal: half a tile edge times sqrt(2).
  double half_diagonal = 0.5 * spacing_[size_t(key.level)] * (kTileGrid - 1) *
                         glm::root_two<double>();
  b.heights = heights_known ? *heights_known : heights().range_near(mid_dir, half_diagonal);
  // Sample the tile's square at both height limits; the surface between
  // samples bulges by at most sag = e^2 / (8 rho) for a sample spacing e.
  constexpr int kSamples = 5;
  std::vector<glm::dvec3> points;
  for (int j = 0; j < kSamples; ++j) {
    for (int i = 0; i < kSamples; ++i) {
      glm::dvec3 dir = cube_to_sphere(key.face, s0 + size * i / (kSamples - 1),
                                      t0 + size * j / (kSamples - 1));
      glm::dvec3 p = ellipsoid_point(shape_, dir);
      glm::dvec3 n = ellipsoid_normal(shape_, p);
      points.push_back(p + b.heights.min * n);
      points.push_back(p + b.heights.max * n);
    }
  }
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const auto& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  b.sphere_center_body = 0.5 * (lo + hi);
  double r = 0;
  for (const auto& p : points) {
    r = std::max(r, glm::length(p - b.sphere_center_body));
    b.max_radius = std::max(b.max_radius, glm::length(p));
  }
  double e = 1.5 * spacing_[size_t(key.level)] * (kTileGrid - 1) / (kSamples - 1);
  double rho = shape_.polar_radius() * shape_.polar_radius() / shape_.equatorial_radius;
  double sag = e * e / (8.0 * rho);
  b.radius = r + sag + 1e-3;
  b.max_radius += sag + 1e-3;
  return b;
}

double TerrainSurface::occluder_radius() const {
  return shape_.polar_radius() + std::min(0.0, heights().range().min);
}

double TerrainSurface::max_radius() const {
  return shape_.equatorial_radius + std::max(0.0, heights().range().max);
}

}  // namespace planet
