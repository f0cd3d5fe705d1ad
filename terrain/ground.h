#pragma once
// Where the ground is under a place: what keeps the pilot above it, checks
// a flight script's keyframes and `planet probe ground` prints.
#include "sim/flight_script.h"
#include "sim/geodesy.h"
#include "terrain/terrain_surface.h"

namespace planet {

// The ground's height above the ellipsoid under a place: where the
// terrain's surface (its height source at full resolution, which every
// tile samples) meets the line from the body's centre through the place.
double ground_height(const TerrainSurface& surface, const Geodesy& geodesy, const Geodetic& place);
// That point of the ground, in the body frame.
glm::dvec3 ground_point(const TerrainSurface& surface, const Geodesy& geodesy,
                        const Geodetic& place);

// What a flight script's "height_above_ground_m" counts from
// (sim/flight_script.h): ground_height on the body's terrain, whose
// surface is made on the first call (not at all for a script without such
// a keyframe) and kept for the calls after it.
GroundHeight terrain_ground();

}  // namespace planet
