#pragma once
// A camera at a geodetic place looking along a heading and pitch, and the
// sun at an elevation and azimuth seen from that place: how the GL tests
// set up a view a person would describe.
#include "sim/camera.h"
#include "sim/geodesy.h"

#include <cmath>

namespace planet {

struct PlaceView {
  Camera camera;
  glm::dvec3 sun_dir_body{0.0};
};

inline PlaceView view_from_place(const Ellipsoid& shape, const Geodetic& place,
                                 double heading_deg, double pitch_deg, double fov_deg,
                                 double sun_elevation_deg, double sun_azimuth_deg) {
  Geodesy geodesy(shape);
  glm::dmat3 body_from_enu = geodesy.body_from_enu(place);
  PlaceView view;
  view.camera.pos_body = geodesy.body_from_geodetic(place);
  view.camera.body_from_camera =
      glm::quat_cast(body_from_enu) *
      enu_from_camera(glm::radians(heading_deg), glm::radians(pitch_deg), 0.0);
  view.camera.vertical_fov = glm::radians(fov_deg);
  double e = glm::radians(sun_elevation_deg), a = glm::radians(sun_azimuth_deg);
  view.sun_dir_body =
      body_from_enu * glm::dvec3(std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e));
  return view;
}

}  // namespace planet
