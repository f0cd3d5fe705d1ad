// Anti-aliased edges of the surfaces against the sky or space. A pixel
// that a surface only partly covers (coverage c in the surface target's
// alpha, from surface_resolve.frag) was shaded as surface where c is at
// least a half, else as open sky along its own ray; here the neighbours of
// the other kind lend it the rest, through blending: c * itself + (1 - c)
// * the open ones' mean, or (1 - c) * itself + c * the covered ones' mean.
// Only whole pixels (fully open or fully covered, which this pass never
// writes) are read. The sky beside a pixel stands in for the sky within
// it: near the ground the horizon's sky changes by a percent or two a
// pixel. From orbit the glow of the limb falls several-fold from one pixel
// to the next, and the glow within the pixel is far brighter than beside
// it: where the neighbours of the other kind differ from the ones a pixel
// further out by more than kSteepest, the pixel keeps the kind that covers
// most of it, as it was shaded.
in vec2 v_ndc;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_radiance;
layout(binding = 1) uniform sampler2D u_surface;
// 1 for an airless body, whose surfaces are the image: what no surface
// covers is black space, and a partly covered pixel is its coverage times
// the covered samples' mean.
uniform int u_open_is_black;

const float kSteepest = 1.25;

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float coverage = texelFetch(u_surface, pixel, 0).a;
  if (coverage <= 0.0 || coverage >= 1.0) discard;
  if (u_open_is_black != 0) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0 - coverage);
    return;
  }
  // The kind the pixel was not shaded as: open (0) or covered (1).
  float other = coverage >= 0.5 ? 0.0 : 1.0;
  ivec2 last = textureSize(u_surface, 0) - 1;
  vec3 sum = vec3(0.0);
  float count = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), last);
      if (texelFetch(u_surface, q, 0).a != other) continue;
      vec3 near = texelFetch(u_radiance, q, 0).rgb;
      ivec2 q2 = clamp(pixel + 2 * ivec2(dx, dy), ivec2(0), last);
      // A neighbour counts only where the one beyond it shows how fast
      // its kind changes.
      if (texelFetch(u_surface, q2, 0).a != other) continue;
      float a = luminance(near), b = luminance(texelFetch(u_radiance, q2, 0).rgb);
      if (max(a, b) > kSteepest * min(a, b)) discard;
      sum += near;
      count += 1.0;
    }
  }
  if (count == 0.0) discard;
  o_color = vec4(sum / count, other == 0.0 ? 1.0 - coverage : coverage);
}
