#include "terrain/ground.h"

#include "terrain/terrain_config.h"

#include <memory>
#include <optional>
#include <string>

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

GroundHeight terrain_ground() {
  struct Surface {
    std::string body;
    std::optional<TerrainSurface> surface;
    std::optional<Geodesy> geodesy;
  };
  auto kept = std::make_shared<Surface>();
  return [kept](const Body& body, const Geodetic& place) {
    if (!kept->surface || kept->body != body.name) {
      kept->surface.emplace(body.shape, parse_terrain(body));
      kept->geodesy.emplace(body.shape);
      kept->body = body.name;
    }
    return ground_height(*kept->surface, *kept->geodesy, place);
  };
}

}  // namespace planet
