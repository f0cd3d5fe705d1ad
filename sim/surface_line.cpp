#include "sim/surface_line.h"

#include <GeographicLib/Geodesic.hpp>

#include <glm/glm.hpp>

namespace planet {

Geodesics::Geodesics(const Ellipsoid& shape)
    : geodesic_(
          std::make_unique<GeographicLib::Geodesic>(shape.equatorial_radius, shape.flattening)) {}
Geodesics::~Geodesics() = default;

SurfaceLine Geodesics::between(const Geodetic& from, const Geodetic& to) const {
  double s12, azi1, azi2;
  geodesic_->Inverse(glm::degrees(from.lat), glm::degrees(from.lon), glm::degrees(to.lat),
                     glm::degrees(to.lon), s12, azi1, azi2);
  return {s12, glm::radians(azi1), glm::radians(azi2)};
}

Geodetic Geodesics::travel(const Geodetic& from, double heading, double distance) const {
  double lat2, lon2;
  geodesic_->Direct(glm::degrees(from.lat), glm::degrees(from.lon), glm::degrees(heading), distance,
                    lat2, lon2);
  return {glm::radians(lat2), glm::radians(lon2), from.height};
}

}  // namespace planet
