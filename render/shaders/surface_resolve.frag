// The surfaces, lit once a pixel at its centre (terrain.frag), and their
// coverage and depth, counted per sample (terrain_coverage.frag), made
// into one surface per pixel for the passes that follow: its radiance,
// the share of its samples a surface covers in alpha (0 where none does),
// and the farthest of its covered samples' depths as the pixel's depth
// (0, the far plane, where none is or fewer than half are). The farthest:
// along Earth's limb from orbit the air in front of the ground glows most
// over the last hundreds of km, and the mean depth left edge pixels 40 %
// too dark; along a ridge from 2 m it brings the edge pixels within 8.4 %
// of a frame of 64 rays a pixel, the centre's depth within 9.0 %. A pixel
// covered whole takes the lit pass's radiance at its centre (a frame of
// one sample a pixel has the same); an edge pixel the mean over its
// covered samples of the lit pass's, interpolated at each from the lit
// pixel centres around it (a surface's light changes little over a pixel;
// the coverage, which changes most, is counted exactly). The atmosphere
// shades a partly covered pixel as the kind that covers at least half of
// it; the edge pass then lays the other kind beside it over the rest
// (surface_edges.frag).
in vec2 v_ndc;
layout(location = 0) out vec4 o_surface;
layout(location = 1) out float o_ground_below;
layout(binding = 0) uniform sampler2D u_lit;
layout(binding = 1) uniform sampler2DMS u_depth;
layout(binding = 2) uniform sampler2DMS u_ground_below;
layout(binding = 3) uniform sampler2D u_lit_depth;
uniform int u_samples;
// Where each sample lies in its pixel, from its lower left corner (0 to 1).
uniform vec2 u_sample_positions[16];

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = 1.0;
  int covered = 0, farthest = 0;
  for (int s = 0; s < u_samples; ++s) {
    float d = texelFetch(u_depth, pixel, s).r;
    if (d > 0.0) {
      if (d < depth) farthest = s;
      depth = min(depth, d);
      ++covered;
    }
  }
  float lit_depth = texelFetch(u_lit_depth, pixel, 0).r;
  vec3 radiance = vec3(0.0);
  if (covered == u_samples && lit_depth > 0.0) {
    radiance = texelFetch(u_lit, pixel, 0).rgb;
  } else if (covered > 0) {
    // Each covered sample's light from the lit pixel centres around it,
    // bilinearly, over those a surface covers; where none of the four
    // does, the nearest lit centre beside the pixel. Loops in a fixed
    // order: the same sums on every run.
    ivec2 last = textureSize(u_lit, 0) - 1;
    int lit = 0;
    for (int s = 0; s < u_samples; ++s) {
      if (texelFetch(u_depth, pixel, s).r <= 0.0) continue;
      vec2 at = u_sample_positions[s] - 0.5;  // from the pixel's centre
      ivec2 base = ivec2(floor(at));
      vec2 f = at - vec2(base);
      vec3 sum = vec3(0.0);
      float weight = 0.0;
      for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
          ivec2 q = pixel + base + ivec2(i, j);
          if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue;
          if (texelFetch(u_lit_depth, q, 0).r <= 0.0) continue;
          float w = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
          sum += w * texelFetch(u_lit, q, 0).rgb;
          weight += w;
        }
      }
      if (weight <= 0.0) {
        float nearest = 1e9;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = pixel + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue;
            vec2 offset = vec2(dx, dy) - at;
            float d = dot(offset, offset);
            if (d < nearest && texelFetch(u_lit_depth, q, 0).r > 0.0) {
              nearest = d;
              sum = texelFetch(u_lit, q, 0).rgb;
              weight = 1.0;
            }
          }
        }
      }
      if (weight > 0.0) {
        radiance += sum / weight;
        ++lit;
      }
    }
    // A sliver no pixel centre near it meets: left open, as one sample a
    // pixel would leave it.
    if (lit == 0) covered = 0;
    else radiance /= float(lit);
  }
  if (covered == 0) {
    o_surface = vec4(0.0);
    o_ground_below = 0.0;
    gl_FragDepth = 0.0;
    return;
  }
  o_surface = vec4(radiance, float(covered) / float(u_samples));
  o_ground_below = texelFetch(u_ground_below, pixel, farthest).r;
  // A pixel less than half covered is the sky's to the atmosphere: it
  // shades the pixel's own ray, and the edge pass lends it the surface.
  gl_FragDepth = 2 * covered < u_samples ? 0.0 : depth;
}
