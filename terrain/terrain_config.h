#pragma once
// The "terrain" object of a body's file: where heights come from, the
// surface palette and the quadtree's depth.
#include "terrain/height_source.h"
#include "terrain/regolith.h"
#include "terrain/surface_color.h"
#include "terrain/surface_maps.h"

#include "sim/body.h"

#include <memory>

namespace planet {

struct TerrainConfig {
  std::shared_ptr<const HeightSource> heights;
  SurfacePalette palette;
  int max_level = 20;             // deepest quadtree level
  std::optional<double> sea_level;  // open sea at this height, if any
  // The wind over the open sea, 12.5 m above it, m/s: the width of the
  // sun's glint (terrain/shaders/sea_brdf.glsl). The "sea" object's
  // "wind_m_s"; 7 m/s, about the oceans' mean, where the file has none.
  double sea_wind = 7.0;
  // Day and night imagery, where the body's file names it and its files
  // are installed; none otherwise (the palette alone then).
  std::shared_ptr<const SurfaceMaps> maps;
  // How the ground reflects sunlight where the body's file says it is
  // regolith (terrain/regolith.h); Lambert's law where it says nothing.
  std::optional<Regolith> regolith;
};

// Reads body.terrain; a body without one gets a smooth ellipsoid (zero
// heights) with a grey palette. Errors name the body file and the field.
// Imagery whose day file is absent is skipped with one note on stderr per
// process (the package that holds it is optional); imagery that is there
// but unreadable is an error.
TerrainConfig parse_terrain(const Body& body);

}  // namespace planet
