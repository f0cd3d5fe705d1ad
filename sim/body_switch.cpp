#include "sim/body_switch.h"

#include "sim/free_flight.h"
#include "sim/sun_ephemeris.h"

#include <algorithm>

namespace planet {

BodySwitch switch_body(const Body& from, const Camera& camera, double height_above_ground,
                       UtcSeconds utc, const Body& to,
                       const std::function<double(const Geodetic&)>& ground_to) {
  Geodesy geodesy_from(from.shape), geodesy_to(to.shape);
  Geodetic old_place = geodesy_from.geodetic_from_body(camera.pos_body);
  glm::dquat enu_from_camera =
      glm::conjugate(glm::quat_cast(geodesy_from.body_from_enu(old_place))) *
      camera.body_from_camera;

  BodySwitch s;
  s.place = Geodetic{old_place.lat, old_place.lon, 0.0};
  s.height_above_ground = std::clamp(height_above_ground, FreeFlight::kClearance,
                                     kSwitchMaxHeightRadii * to.shape.equatorial_radius);
  s.height_clamped = s.height_above_ground != height_above_ground;
  s.place.height = ground_to(s.place) + s.height_above_ground;
  s.camera = camera;
  s.camera.pos_body = geodesy_to.body_from_geodetic(s.place);
  s.camera.body_from_camera =
      glm::normalize(glm::quat_cast(geodesy_to.body_from_enu(s.place)) * enu_from_camera);

  s.utc = utc;
  if (from.ephemeris.available()) {
    s.sun_hour_angle =
        sun_hour_angle(sun_dir_body(from.ephemeris, from.rotation, utc), old_place.lon);
    s.utc = utc_at_sun_hour_angle(to.ephemeris, to.rotation, old_place.lon, s.sun_hour_angle, utc);
  }
  return s;
}

}  // namespace planet
