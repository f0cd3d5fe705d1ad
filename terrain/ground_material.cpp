// Earth's ground materials' one C++ translation unit: the GLSL file
// compiled in double (see ground_material.h), in a namespace of its own
// because it declares the struct the header does.
#include "terrain/ground_material.h"

namespace planet::materials {

namespace glsl {
using namespace glm;
#include "terrain/shaders/ground_material.glsl"

planet::materials::GroundMaterial out(const GroundMaterial& m) {
  return {m.snow, m.rock, m.forest, m.grass, m.desert, m.albedo};
}
}  // namespace glsl

const Real3 kSnowAlbedo = glsl::kSnowAlbedo, kRockAlbedo = glsl::kRockAlbedo,
            kForestAlbedo = glsl::kForestAlbedo, kGrassAlbedo = glsl::kGrassAlbedo,
            kDesertAlbedo = glsl::kDesertAlbedo;

Real earth_snow_line(Real latitude) { return glsl::earth_snow_line(latitude); }

GroundMaterial image_material(Real3 c) { return glsl::out(glsl::image_material(c)); }

GroundMaterial ground_material(Real slope, Real height, Real latitude, Real3 c, bool has_image) {
  return glsl::out(glsl::ground_material(slope, height, latitude, c, has_image));
}

Real ground_image_cover(Real slope, Real height, Real latitude) {
  return glsl::ground_image_cover(slope, height, latitude);
}

}  // namespace planet::materials
