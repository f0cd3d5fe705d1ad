// The 8 x 8 pixel tiles of a frame on hillaire's LUT path whose pixels may
// want the per-pixel march (hillaire_sky.frag: a surface past the start of
// the froxels' blend, 0.8 of their range), appended to a list that an
// indirect draw of one quad per tile reads (sky_tiles.vert). A superset:
// the sky pass decides pixel by pixel, and a pixel that wants no march
// comes out the same from either part.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D u_depth;
uniform mat3 u_ray_from_ndc;
uniform float u_near;
uniform vec2 u_viewport;
uniform float u_blend_start;  // metres along the ray

#include "atmosphere/gpu/hillaire/sky_march_tiles.glsl"

shared uint any_marched;

void main() {
  if (gl_LocalInvocationIndex == 0u) any_marched = 0u;
  barrier();
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(vec2(pixel), u_viewport))) {
    float depth = texelFetch(u_depth, pixel, 0).r;
    vec2 ndc = (vec2(pixel) + 0.5) / u_viewport * 2.0 - 1.0;
    float ray_scale = length(u_ray_from_ndc * vec3(ndc, 1.0));
    // A hair short of the start, for the rounding between here and there.
    if (depth > 0.0 && ray_scale * u_near / depth > 0.999 * u_blend_start) {
      atomicOr(any_marched, 1u);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && any_marched != 0u) {
    tiles[atomicAdd(instance_count, 1u)] = gl_WorkGroupID.xy;
  }
}
