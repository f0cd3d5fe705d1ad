#include "terrain/sun_shadow_field.h"

#include "core/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace planet {

namespace {

// The sun's components in the patch's frame are rounded to this.
constexpr double kSunStep = 1e-4;
// Below this sine of the sun's elevation at a cell (about -5.7 degrees),
// the planet's own shadow covers every altitude the terrain could shade.
constexpr double kSunBelowRelief = -0.1;

// A grid of n x n cell values at a point of the plane given in cells from
// the patch's corner, bilinear between cell centres, clamped at the edge.
double bilinear(const std::vector<float>& grid, int n, double u, double v) {
  u = std::clamp(u - 0.5, 0.0, double(n - 1));
  v = std::clamp(v - 0.5, 0.0, double(n - 1));
  const int i0 = std::min(int(u), n - 2), j0 = std::min(int(v), n - 2);
  const double fu = u - i0, fv = v - j0;
  auto at = [&](int i, int j) { return double(grid[size_t(j) * size_t(n) + size_t(i)]); };
  return (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) +
         fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
}

}  // namespace

bool ShadowPatch::plane(const glm::dvec3& q, double& x, double& y) const {
  const double c = glm::dot(q, up);
  if (c <= 1e-3) return false;
  x = bottom_radius * glm::dot(q, east) / c;
  y = bottom_radius * glm::dot(q, north) / c;
  return true;
}

SunShadowField::SunShadowField(int size, double half_side) : size_(size), half_side_(half_side) {}

double SunShadowField::ground_at(double x, double y) const {
  const double cells = size_ / (2.0 * half_side_);
  return bilinear(ground_, size_, (x + half_side_) * cells, (y + half_side_) * cells);
}

double SunShadowField::shadow_height(double x, double y) const {
  const double cells = size_ / (2.0 * half_side_);
  return bilinear(shadow_, size_, (x + half_side_) * cells, (y + half_side_) * cells);
}

bool SunShadowField::update(const TerrainSurface& surface, const glm::dvec3& atmo_scale,
                            double bottom_radius, const glm::dvec3& camera_atmo,
                            const glm::dvec3& sun_atmo) {
  // The centre: the camera's direction snapped to a lattice of latitude and
  // longitude an eighth of the patch apart on the ground.
  const double r = glm::length(camera_atmo);
  const glm::dvec3 dir = r > 0 ? camera_atmo / r : glm::dvec3(0, 0, 1);
  const double step = half_side_ / 4.0 / bottom_radius;
  const double half_pi = 0.5 * std::acos(-1.0);
  const double lat = std::clamp(std::round(std::asin(std::clamp(dir.z, -1.0, 1.0)) / step) * step,
                                -half_pi + step, half_pi - step);
  const double lon_step = step / std::max(std::cos(lat), 0.05);
  const double lon = std::round(std::atan2(dir.y, dir.x) / lon_step) * lon_step;
  const glm::dvec3 centre(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                          std::sin(lat));

  const bool new_ground = centre != centre_ || &surface != surface_ || atmo_scale != scale_ ||
                          bottom_radius != patch_.bottom_radius || ground_.empty();
  if (new_ground) {
    centre_ = centre;
    surface_ = &surface;
    scale_ = atmo_scale;
    patch_.up = centre;
    patch_.east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), centre));
    patch_.north = glm::cross(centre, patch_.east);
    patch_.bottom_radius = bottom_radius;
    patch_.half_side = half_side_;
    patch_.size = size_;
    ground_.assign(size_t(size_) * size_t(size_), 0.0f);
    const double cell = patch_.cell();
    parallel_for(size_, 0, [&](int j) {
      for (int i = 0; i < size_; ++i) {
        const double x = (i + 0.5) * cell - half_side_, y = (j + 0.5) * cell - half_side_;
        const glm::dvec3 q = glm::normalize(patch_.up + (x / bottom_radius) * patch_.east +
                                            (y / bottom_radius) * patch_.north);
        const glm::dvec3 g = atmo_scale * surface.point(glm::normalize(q / atmo_scale));
        ground_[size_t(j) * size_t(size_) + size_t(i)] = float(glm::length(g) - bottom_radius);
      }
    });
    ground_max_ = *std::max_element(ground_.begin(), ground_.end());
  }

  // The sun in the patch's frame, rounded.
  auto round_sun = [](double c) { return std::round(c / kSunStep) * kSunStep; };
  const glm::dvec3 local(round_sun(glm::dot(sun_atmo, patch_.east)),
                         round_sun(glm::dot(sun_atmo, patch_.north)),
                         round_sun(glm::dot(sun_atmo, patch_.up)));
  const glm::dvec3 sun =
      glm::normalize(local.x * patch_.east + local.y * patch_.north + local.z * patch_.up);
  if (!new_ground && sun == sun_) return false;
  sun_ = sun;
  compute_shadow(sun);
  ++version_;
  return true;
}

void SunShadowField::compute_shadow(const glm::dvec3& sun) {
  shadow_.assign(ground_.size(), 0.0f);
  const double R = patch_.bottom_radius, cell = patch_.cell();
  const double inside = half_side_ - 0.5 * cell;
  parallel_for(size_, 0, [&](int j) {
    for (int i = 0; i < size_; ++i) {
      const size_t n = size_t(j) * size_t(size_) + size_t(i);
      const double x0 = (i + 0.5) * cell - half_side_, y0 = (j + 0.5) * cell - half_side_;
      const glm::dvec3 q0 =
          glm::normalize(patch_.up + (x0 / R) * patch_.east + (y0 / R) * patch_.north);
      const double h0 = ground_[n];
      double best = h0;
      const double sin_e = glm::dot(sun, q0);
      if (sin_e >= kSunBelowRelief) {
        // Steps that advance a cell over the ground near the cell, and a
        // thirty-second of a cell more with each step: the far ground's
        // shadow needs less detail than the near, and a march across the
        // whole patch at a sun on the horizon takes 75 steps, not 160.
        const double cos_e = std::sqrt(std::max(1.0 - sin_e * sin_e, 0.0));
        const double d_cell = cell / std::max(cos_e, 0.05);
        const glm::dvec3 p0 = (R + h0) * q0;
        double previous_gain = 0.0, d = 0.0;
        for (int k = 1; k <= 4 * size_; ++k) {
          d += d_cell * (1.0 + k / 32.0);
          const glm::dvec3 p = p0 + d * sun;
          const double r = glm::length(p);
          double x, y;
          if (!patch_.plane(p / r, x, y) || std::abs(x) > inside || std::abs(y) > inside) break;
          // How far the sun's ray has risen above where it left the ground.
          const double gain = r - R - h0;
          best = std::max(best, ground_at(x, y) - gain);
          // Rising, and above the highest ground already by more than the
          // best: nothing farther can shade the cell.
          if (gain > previous_gain && ground_max_ - gain <= best) break;
          previous_gain = gain;
        }
      }
      shadow_[n] = float(best);
    }
  });
  highest_ = -std::numeric_limits<double>::infinity();
  for (size_t n = 0; n < shadow_.size(); ++n) {
    if (shadow_[n] > ground_[n] + 1.0f) highest_ = std::max(highest_, double(shadow_[n]));
  }
}

}  // namespace planet
