#pragma once
// Geodetic coordinates on a body's ellipsoid, and the frames that hang off
// them. Positions in the body-fixed frame are in double, always.
#include "sim/body.h"
#include "sim/camera.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <memory>

namespace GeographicLib {
class Geocentric;
}

namespace planet {

struct Geodetic {
  double lat = 0;     // geodetic latitude, radians
  double lon = 0;     // longitude, radians
  double height = 0;  // above the ellipsoid, metres
};

class Geodesy {
 public:
  explicit Geodesy(const Ellipsoid& shape);
  ~Geodesy();
  Geodesy(Geodesy&&) noexcept;
  Geodesy& operator=(Geodesy&&) noexcept;

  glm::dvec3 body_from_geodetic(const Geodetic& g) const;
  Geodetic geodetic_from_body(const glm::dvec3& pos_body) const;

  // Columns are east, north and up at the given place, in the body frame.
  glm::dmat3 body_from_enu(const Geodetic& g) const;

  // A camera at a place, looking along heading (clockwise from north) and
  // pitch (up positive), radians (enu_from_camera, no roll).
  Camera camera_at(const Geodetic& g, double heading, double pitch, double vertical_fov) const;
  // The direction at elevation and azimuth (clockwise from north), radians,
  // seen from a place: a sun or a look direction as a person gives it.
  glm::dvec3 body_direction(const Geodetic& g, double elevation, double azimuth) const;

  const Ellipsoid& shape() const { return shape_; }

 private:
  Ellipsoid shape_;
  std::unique_ptr<GeographicLib::Geocentric> geocentric_;
};

// Camera attitude from heading (clockwise from north), pitch (up positive)
// and roll (right wing down positive), all radians, relative to the local
// east-north-up frame. The camera looks along its -z, with +y up and +x
// right, as OpenGL's view space does. The returned rotation maps camera
// axes into ENU axes.
glm::dquat enu_from_camera(double heading, double pitch, double roll);

// The inverse of enu_from_camera: heading in [0, 2 pi), pitch in
// [-pi / 2, pi / 2] and roll in (-pi, pi], radians. Looking straight up or
// down, heading and roll share one turn; the heading is then that of the
// camera's top.
struct LookAngles {
  double heading = 0, pitch = 0, roll = 0;
};
LookAngles look_angles(const glm::dquat& enu_from_camera);

}  // namespace planet
