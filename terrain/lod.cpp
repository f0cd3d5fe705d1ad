#include "terrain/lod.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

bool LodSelector::in_frustum(const TileBounds& b, const LodView& view) const {
  glm::dvec3 c = view.view_from_body * (b.sphere_center_body - view.eye_body);
  double tx = view.tan_half_fov_y * view.aspect, ty = view.tan_half_fov_y;
  // Side planes through the eye, normals (+-1, 0, tan) / |.| pointing out.
  double nx = 1.0 / std::sqrt(1.0 + tx * tx), ny = 1.0 / std::sqrt(1.0 + ty * ty);
  if ((c.x + c.z * tx) * nx > b.radius) return false;
  if ((-c.x + c.z * tx) * nx > b.radius) return false;
  if ((c.y + c.z * ty) * ny > b.radius) return false;
  if ((-c.y + c.z * ty) * ny > b.radius) return false;
  return c.z < b.radius;  // not wholly behind the eye
}

bool LodSelector::above_horizon(const TileBounds& b, const LodView& view) const {
  // Occluder: the sphere of the body's lowest ground, which lies inside
  // the body everywhere, so the test can only keep too much. From the eye
  // at distance D the sphere hides everything beyond the angle
  // acos(R / D) + acos(R / r) from the eye's direction, for a point at
  // distance r from the centre (the two tangent lines meet there).
  double R = surface_->occluder_radius();
  double D = glm::length(view.eye_body);
  if (D <= R) return true;
  double r = glm::length(b.sphere_center_body);
  if (r <= b.radius) return true;  // the sphere holds the centre: a root tile
  double r_top = r + b.radius;
  if (r_top <= R) return false;
  double angle = std::acos(std::clamp(glm::dot(view.eye_body, b.sphere_center_body) / (D * r),
                                      -1.0, 1.0));
  double angular_radius = std::asin(std::min(1.0, b.radius / r));
  return angle - angular_radius <= std::acos(R / D) + std::acos(R / r_top);
}

const TileBounds& LodSelector::bounds(const TileKey& key) const {
  auto it = bounds_.find(key);
  if (it != bounds_.end()) return it->second;
  if (bounds_.size() >= kKeptBounds) bounds_.clear();
  return bounds_.emplace(key, surface_->bounds(key)).first->second;
}

const TileBounds& LodSelector::resident_bounds(const TileKey& key,
                                               const HeightRange& heights) const {
  auto it = resident_bounds_.find(key);
  // A tile's grid is the same whenever it is built: the heights change only
  // if the key's tile was rebuilt from another source, and then so do its bounds.
  if (it != resident_bounds_.end() && it->second.heights.min == heights.min &&
      it->second.heights.max == heights.max) {
    return it->second;
  }
  if (resident_bounds_.size() >= kKeptBounds) resident_bounds_.clear();
  return resident_bounds_.insert_or_assign(key, surface_->bounds(key, &heights)).first->second;
}

void LodSelector::visit(const TileKey& key, const ResidentTile& tile, double parent_error,
                        const LodView& view, const TileErrorLookup& resident_error,
                        LodSelection& out) const {
  ++out.visited;
  const double error = tile.error;
  // Copies: the kept bounds may be emptied by the visits below.
  const TileBounds own = resident_bounds(key, tile.heights);
  // The eye's distance to the tile is at least its distance to the
  // bounding sphere, and at least its height above the tile's highest point.
  double distance =
      std::max({glm::length(own.sphere_center_body - view.eye_body) - own.radius,
                glm::length(view.eye_body) - own.max_radius, 0.0});
  double error_px = distance > 0 ? error * view.pixels_per_radian() / distance : 1e30;
  if (error_px > view.pixel_budget && key.level < surface_->config().max_level) {
    TileBounds child_bounds[4];
    ResidentTile child_tile[4];
    bool visible[4], all_resident = true;
    for (int i = 0; i < 4; ++i) {
      TileKey c = key.child(i);
      child_bounds[i] = bounds(c);
      visible[i] = true;
      if (!in_frustum(child_bounds[i], view)) {
        visible[i] = false;
        ++out.culled_frustum;
      } else if (!above_horizon(child_bounds[i], view)) {
        visible[i] = false;
        ++out.culled_horizon;
      }
      if (visible[i] && !resident_error(c, child_tile[i])) {
        all_resident = false;
        out.wanted.push_back(c);
      }
    }
    if (all_resident) {
      for (int i = 0; i < 4; ++i) {
        if (visible[i]) {
          visit(key.child(i), child_tile[i], error, view, resident_error, out);
        }
      }
      return;
    }
  }
  SelectedTile t;
  t.key = key;
  t.center_body = own.center_body;
  t.distance = distance;
  t.error_px = error_px;
  if (key.level > 0) {
    t.morph_end = split_distance(parent_error, view);
    t.morph_start = 0.6 * t.morph_end;
  } else {
    t.morph_start = t.morph_end = 1e30;  // roots have no parent to morph into
  }
  out.tiles.push_back(t);
}

LodSelection LodSelector::select(const LodView& view,
                                 const TileErrorLookup& resident_error) const {
  LodSelection out;
  for (int face = 0; face < 6; ++face) {
    TileKey root{face, 0, 0, 0};
    const TileBounds b = bounds(root);
    if (!in_frustum(b, view)) {
      ++out.culled_frustum;
      continue;
    }
    if (!above_horizon(b, view)) {
      ++out.culled_horizon;
      continue;
    }
    ResidentTile tile;
    if (!resident_error(root, tile)) {
      out.wanted.push_back(root);
      continue;
    }
    visit(root, tile, 0.0, view, resident_error, out);
  }
  // Coarse tiles first: they fill holes; then the nearest.
  std::stable_sort(out.wanted.begin(), out.wanted.end(),
                   [](const TileKey& a, const TileKey& b) { return a.level < b.level; });
  return out;
}

}  // namespace planet
