#include "sim/geodesy.h"

#include <GeographicLib/Geocentric.hpp>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <vector>

namespace planet {

Geodesy::Geodesy(const Ellipsoid& shape)
    : shape_(shape),
      geocentric_(
          std::make_unique<GeographicLib::Geocentric>(shape.equatorial_radius, shape.flattening)) {}
Geodesy::~Geodesy() = default;
Geodesy::Geodesy(Geodesy&&) noexcept = default;
Geodesy& Geodesy::operator=(Geodesy&&) noexcept = default;

glm::dvec3 Geodesy::body_from_geodetic(const Geodetic& g) const {
  glm::dvec3 p;
  geocentric_->Forward(glm::degrees(g.lat), glm::degrees(g.lon), g.height, p.x, p.y, p.z);
  return p;
}

Geodetic Geodesy::geodetic_from_body(const glm::dvec3& pos_body) const {
  double lat_deg, lon_deg, h;
  geocentric_->Reverse(pos_body.x, pos_body.y, pos_body.z, lat_deg, lon_deg, h);
  return {glm::radians(lat_deg), glm::radians(lon_deg), h};
}

glm::dmat3 Geodesy::body_from_enu(const Geodetic& g) const {
  double sl = std::sin(g.lat), cl = std::cos(g.lat);
  double so = std::sin(g.lon), co = std::cos(g.lon);
  glm::dvec3 east(-so, co, 0.0);
  glm::dvec3 north(-sl * co, -sl * so, cl);
  glm::dvec3 up(cl * co, cl * so, sl);
  return glm::dmat3(east, north, up);
}

Camera Geodesy::camera_at(const Geodetic& g, double heading, double pitch,
                          double vertical_fov) const {
  Camera camera;
  camera.pos_body = body_from_geodetic(g);
  camera.body_from_camera = glm::quat_cast(body_from_enu(g)) * enu_from_camera(heading, pitch, 0.0);
  camera.vertical_fov = vertical_fov;
  return camera;
}

glm::dvec3 Geodesy::body_direction(const Geodetic& g, double elevation, double azimuth) const {
  glm::dvec3 enu(std::sin(azimuth) * std::cos(elevation), std::cos(azimuth) * std::cos(elevation),
                 std::sin(elevation));
  return body_from_enu(g) * enu;
}

glm::dquat enu_from_camera(double heading, double pitch, double roll) {
  // Level camera looking north: camera -z -> north (+y), +y -> up (+z),
  // +x -> east (+x).
  glm::dmat3 level(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  glm::dquat base = glm::quat_cast(level);
  // Heading turns clockwise seen from above: a negative turn about up.
  glm::dquat yaw = glm::angleAxis(-heading, glm::dvec3(0, 0, 1));
  // Pitch about the camera's right axis, roll about its forward (-z) axis.
  glm::dquat pitch_q = glm::angleAxis(pitch, glm::dvec3(1, 0, 0));
  glm::dquat roll_q = glm::angleAxis(-roll, glm::dvec3(0, 0, 1));
  return glm::normalize(yaw * base * pitch_q * roll_q);
}

LookAngles look_angles(const glm::dquat& enu_from_camera) {
  glm::dvec3 forward = enu_from_camera * glm::dvec3(0, 0, -1);
  glm::dvec3 right = enu_from_camera * glm::dvec3(1, 0, 0);
  glm::dvec3 top = enu_from_camera * glm::dvec3(0, 1, 0);
  LookAngles a;
  a.pitch = std::asin(glm::clamp(forward.z, -1.0, 1.0));
  // Straight up or down the forward axis has no heading: the top's (or,
  // looking up, its opposite's) stands in for it.
  glm::dvec3 level = std::abs(forward.z) < 1.0 - 1e-12 ? forward : -forward.z * top;
  a.heading = std::atan2(level.x, level.y);
  if (a.heading < 0) a.heading += 2.0 * glm::pi<double>();
  if (a.heading >= 2.0 * glm::pi<double>()) a.heading = 0;  // -1e-17 wrapped
  // Roll, right wing down positive: the right axis below the horizon.
  a.roll = std::atan2(-right.z, top.z);
  return a;
}

}  // namespace planet
