#pragma once
// The frame's terrain shadow (SkyTerrainShadow) handed to a program compiled
// with TERRAIN_SHADOWS (terrain_shadow.glsl): texture unit 9 and its
// uniforms. Without a field, the program's shadow strength is 0 and the
// sun is never hidden.
#include "atmosphere/gpu/technique.h"
#include "gl/program.h"

namespace planet {

// Texture unit of the shadow heights (terrain_shadow.glsl's binding).
constexpr GLuint kTerrainShadowUnit = 9;
// The sun comes in over these metres of altitude above a shadow's height
// (its disc, and the field's cells).
constexpr float kTerrainShadowSoftness = 60.0f;

// The program must be in use.
void bind_terrain_shadow(const Program& program, const SkyTerrainShadow& shadow);

}  // namespace planet
