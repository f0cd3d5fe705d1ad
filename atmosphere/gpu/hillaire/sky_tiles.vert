// One quad per tile of sky_march_tiles.comp's list (instance i: tile i),
// in pixels of u_viewport, clamped to it.
#define TILES_ACCESS readonly
#include "atmosphere/gpu/hillaire/sky_march_tiles.glsl"
uniform vec2 u_viewport;

void main() {
  // Two triangles: corners (0,0) (1,0) (0,1), (0,1) (1,0) (1,1).
  const vec2 corners[6] =
      vec2[6](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(0, 1), vec2(1, 0), vec2(1, 1));
  vec2 p = min((vec2(tiles[gl_InstanceID]) + corners[gl_VertexID]) * 8.0, u_viewport);
  gl_Position = vec4(p / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
