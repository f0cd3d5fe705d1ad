#include "atmosphere/screen_bound.h"

#include <algorithm>
#include <cmath>

namespace planet {

std::optional<NdcRect> sphere_ndc_bound(const glm::dvec3& center, double radius,
                                        const glm::dmat3& ray_from_ndc) {
  const double d = glm::length(center);
  if (d <= radius * (1.0 + 1e-9)) return std::nullopt;
  const glm::dvec3 c = center / d;
  const double sin2 = (radius / d) * (radius / d), cos2 = 1.0 - sin2;
  // The cone of directions v that meet the sphere: v^T B v <= 0 with
  // B = cos^2 I - c c^T. In q = (x w, y w, w), v = M q: the cone's matrix is
  // M^T B M and its dual D = M^-1 B^-1 M^-T, where B^-1 = (I - c c^T) / cos^2
  // - c c^T / sin^2. A plane through the camera with normal n touches the
  // cone where n^T D n = 0 and misses it where n^T D n < 0.
  const glm::dmat3 cc = glm::outerProduct(c, c);
  const glm::dmat3 b_inverse = (glm::dmat3(1.0) - cc) / cos2 - cc / sin2;
  const glm::dmat3 m_inverse = glm::inverse(ray_from_ndc);
  const glm::dmat3 dual = m_inverse * b_inverse * glm::transpose(m_inverse);
  // glm is column-major: dual[col][row]. Index 2 is w.
  const double dww = dual[2][2];
  // The plane w = 0 must miss the cone, and the cone lie on the side w > 0.
  if (!(dww < 0.0) || (m_inverse * c).z <= 0.0) return std::nullopt;
  NdcRect rect;
  for (int axis = 0; axis < 2; ++axis) {
    // n = e_axis - k e_w: D_aa - 2 k D_aw + k^2 D_ww = 0.
    const double daa = dual[axis][axis], daw = dual[2][axis];
    const double disc = daw * daw - daa * dww;
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(disc);
    const double k0 = (daw + root) / dww, k1 = (daw - root) / dww;
    rect.min[axis] = std::min(k0, k1);
    rect.max[axis] = std::max(k0, k1);
  }
  return rect;
}

}  // namespace planet
