#pragma once
// Where the benchmarks put their cameras: a height above the ground under
// the place, as `fly --height` takes it, so that a view "from 2 m" is
// 2 m over the terrain and not inside a mountain (2 m above the ellipsoid
// at 46.5 N, 8 E is 1329 m under the Alps' ground).
#include "sim/body.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"

namespace planet {

inline Geodetic above_ground(const Body& body, Geodetic place) {
  TerrainSurface surface(body.shape, parse_terrain(body));
  place.height += ground_height(surface, Geodesy(body.shape), place);
  return place;
}

}  // namespace planet
