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

inline PlaceView view_from_place(const Ellipsoid& shape, const Geodetic& place, double heading_deg,
                                 double pitch_deg, double fov_deg, double sun_elevation_deg,
                                 double sun_azimuth_deg) {
  Geodesy geodesy(shape);
  PlaceView view;
  view.camera = geodesy.camera_at(place, glm::radians(heading_deg), glm::radians(pitch_deg),
                                  glm::radians(fov_deg));
  view.sun_dir_body =
      geodesy.body_direction(place, glm::radians(sun_elevation_deg), glm::radians(sun_azimuth_deg));
  return view;
}

}  // namespace planet
