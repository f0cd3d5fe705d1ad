#include "terrain/ground.h"

namespace planet {

glm::dvec3 ground_point(const TerrainSurface& surface, const Geodesy& geodesy,
                        const Geodetic& place) {
  Geodetic on_ellipsoid = place;
  on_ellipsoid.height = 0.0;
  return surface.point(glm::normalize(geodesy.body_from_geodetic(on_ellipsoid)));
}

double ground_height(const TerrainSurface& surface, const Geodesy& geodesy, const Geodetic& place) {
  return geodesy.geodetic_from_body(ground_point(surface, geodesy, place)).height;
}

}  // namespace planet
