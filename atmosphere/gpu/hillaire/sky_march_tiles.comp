// The 8 x 8 pixel tiles of a frame on hillaire's LUT path whose pixels may
// want the per-pixel march (hillaire_sky.frag: a surface past the start of
// the froxels' blend, 0.8 of their range), appended to a list that an
// indirect draw of one quad per tile reads (sky_tiles.vert). A superset:
// the sky pass decides pixel by pixel, and a pixel that wants no march
// comes out the same from either part.
//
// One invocation a tile, which reads its pixels itself: llvmpipe runs a
// workgroup's barrier() by switching between its invocations one by one,
// and with one invocation a pixel, a barrier around a shared flag, the
// listing took 20 ms of a 60 ms sky pass at 1280x720 on the ground.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D u_depth;
uniform mat3 u_ray_from_ndc;
uniform float u_near;
uniform vec2 u_viewport;
uniform float u_blend_start;  // metres along the ray

#include "atmosphere/gpu/hillaire/sky_march_tiles.glsl"

const int kTile = 8;

void main() {
  ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
  ivec2 first = tile * kTile;
  ivec2 end = min(first + kTile, ivec2(u_viewport));
  if (any(greaterThanEqual(first, end))) return;
  bool marched = false;
  for (int y = first.y; y < end.y && !marched; ++y) {
    for (int x = first.x; x < end.x && !marched; ++x) {
      float depth = texelFetch(u_depth, ivec2(x, y), 0).r;
      vec2 ndc = (vec2(x, y) + 0.5) / u_viewport * 2.0 - 1.0;
      float ray_scale = length(u_ray_from_ndc * vec3(ndc, 1.0));
      // A hair short of the start, for the rounding between here and there.
      marched = depth > 0.0 && ray_scale * u_near / depth > 0.999 * u_blend_start;
    }
  }
  if (marched) tiles[atomicAdd(instance_count, 1u)] = uvec2(tile);
}
