// The surfaces' multisampled pass resolved for the passes that follow,
// which take one surface per pixel: the mean radiance of the samples that
// a surface covers, their coverage in alpha (0 where none does), and the
// farthest of their depths as the pixel's depth (0, the far plane, where
// none does or fewer than half do). The farthest: along Earth's limb from
// orbit the air in front of the ground glows most over the last hundreds
// of km, and the mean depth left edge pixels 40 % too dark. The atmosphere shades a partly
// covered pixel as the kind that covers at least half of it; the edge pass
// then lays the other kind beside it over the rest (surface_edges.frag).
in vec2 v_ndc;
// How far the ground lies below the datum comes from that farthest sample.
layout(location = 0) out vec4 o_surface;
layout(location = 1) out float o_ground_below;
layout(binding = 0) uniform sampler2DMS u_color;
layout(binding = 1) uniform sampler2DMS u_depth;
layout(binding = 2) uniform sampler2DMS u_ground_below;
uniform int u_samples;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 radiance = vec3(0.0);
  float depth = 1.0;
  int covered = 0, farthest = 0;
  for (int s = 0; s < u_samples; ++s) {
    float d = texelFetch(u_depth, pixel, s).r;
    if (d > 0.0) {
      radiance += texelFetch(u_color, pixel, s).rgb;
      if (d < depth) farthest = s;
      depth = min(depth, d);
      ++covered;
    }
  }
  if (covered == 0) {
    o_surface = vec4(0.0);
    o_ground_below = 0.0;
    gl_FragDepth = 0.0;
    return;
  }
  o_surface = vec4(radiance / float(covered), float(covered) / float(u_samples));
  o_ground_below = texelFetch(u_ground_below, pixel, farthest).r;
  // A pixel less than half covered is the sky's to the atmosphere: it
  // shades the pixel's own ray, and the edge pass lends it the surface.
  gl_FragDepth = 2 * covered < u_samples ? 0.0 : depth;
}
