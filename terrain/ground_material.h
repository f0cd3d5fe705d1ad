#pragma once
// Earth's ground materials by rule (terrain/shaders/ground_material.glsl,
// compiled in double in ground_material.cpp): rock where slope or height
// lays it bare, snow above a snow line that falls with latitude, and
// forest, grass or sand where the day image's colour says so. The tiles'
// vertices take their albedo from it, the shader its far field, and the
// tests probe it. See docs/surfaces.md#materials.
#include <glm/glm.hpp>

namespace planet::materials {

using Real = double;
using Real3 = glm::dvec3;

struct GroundMaterial {
  Real snow;
  Real rock;
  Real forest;
  Real grass;
  Real desert;
  Real3 albedo;
};

extern const Real3 kSnowAlbedo, kRockAlbedo, kForestAlbedo, kGrassAlbedo, kDesertAlbedo;

// Metres above the sea, for a latitude in radians.
Real earth_snow_line(Real latitude);
// The materials that a day image's colour (display sRGB, [0, 1]) shows.
GroundMaterial image_material(Real3 c);
// `slope`: 1 - cos of the ground's tilt; `height`: metres above the sea;
// `latitude`: geodetic, radians; `c`: the day image's colour there.
GroundMaterial ground_material(Real slope, Real height, Real latitude, Real3 c, bool has_image);
// The share of a land point's colour the day image gives beyond the fade.
Real ground_image_cover(Real slope, Real height, Real latitude);

}  // namespace planet::materials
