// The list of 8 x 8 pixel tiles that sky_march_tiles.comp writes and
// sky_tiles.vert draws (hillaire_sky.frag's march): an indirect draw's
// DrawArraysIndirectCommand, then the tiles (x, y in tiles). The drawing
// side defines TILES_ACCESS readonly.
#ifndef TILES_ACCESS
#define TILES_ACCESS
#endif
layout(std430, binding = 4) TILES_ACCESS buffer Tiles {
  uint vertex_count;
  uint instance_count;
  uint first_vertex;
  uint base_instance;
  uvec2 tiles[];
};
