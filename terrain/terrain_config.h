#pragma once
// The "terrain" object of a body's file: where heights come from, the
// surface palette and the quadtree's depth.
#include "terrain/height_source.h"
#include "terrain/surface_color.h"

#include "sim/body.h"

#include <memory>

namespace planet {

struct TerrainConfig {
  std::shared_ptr<const HeightSource> heights;
  SurfacePalette palette;
  int max_level = 20;             // deepest quadtree level
  std::optional<double> sea_level;  // open sea at this height, if any
};

// Reads body.terrain; a body without one gets a smooth ellipsoid (zero
// heights) with a grey palette. Errors name the body file and the field.
TerrainConfig parse_terrain(const Body& body);

}  // namespace planet
