#pragma once
// Where a switch of body puts the pilot (fly's B key and body list): over
// the same latitude and longitude, at the same height above the ground
// (clamped to what the new body allows), looking the same way in the local
// east-north-up frame, at the same local solar time. The place and the time
// of day are what a pilot knows of where they were; a body's named start
// would lose both, and the same UTC instant puts the sun anywhere (the Alps
// at 10:30 in the morning are in the Martian night at the same instant).
#include "sim/body.h"
#include "sim/camera.h"
#include "sim/geodesy.h"
#include "sim/utc_time.h"

#include <functional>

namespace planet {

// Heights above the ground a switch keeps: from the free flight's clearance
// up to this many of the new body's radii (from higher, a small body would
// be a dot: 400 km above the Earth is 13 radii of a 30 km asteroid).
constexpr double kSwitchMaxHeightRadii = 1.0;

struct BodySwitch {
  Camera camera;                   // on the new body
  Geodetic place;                  // its height above the new body's ellipsoid
  double height_above_ground = 0;  // kept, after the clamp
  bool height_clamped = false;     // the height was out of the new body's range
  UtcSeconds utc = 0;              // the clock's new instant
  double sun_hour_angle = 0;       // kept from the old place, radians
};

// `camera` flies over `from` at `utc`, `height_above_ground` metres over its
// ground; `ground_to` gives the new body's ground height above its
// ellipsoid under a place.
BodySwitch switch_body(const Body& from, const Camera& camera, double height_above_ground,
                       UtcSeconds utc, const Body& to,
                       const std::function<double(const Geodetic&)>& ground_to);

}  // namespace planet
