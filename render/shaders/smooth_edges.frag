// Lottes 2009, FXAA: the tone-mapped image's edges blended along their
// direction, found from the luma of the four diagonal neighbours. For a
// window whose surfaces cannot take multisampling (llvmpipe shades each of
// its samples: the coverage's alone doubles the surfaces' pass); a capture
// multisamples instead (frame.h's FrameOptions::antialiasing).
in vec2 v_ndc;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_ldr;

// Lottes' defaults: no edge below an eighth of the local luma (or 1/128),
// and a blend at most 8 pixels long.
const float kReduceMin = 1.0 / 128.0;
const float kReduceMul = 1.0 / 8.0;
const float kSpanMax = 8.0;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main() {
  vec2 px = 1.0 / vec2(textureSize(u_ldr, 0));
  vec2 uv = gl_FragCoord.xy * px;
  vec3 centre = texelFetch(u_ldr, ivec2(gl_FragCoord.xy), 0).rgb;
  float nw = luma(texture(u_ldr, uv + vec2(-1.0, -1.0) * px).rgb);
  float ne = luma(texture(u_ldr, uv + vec2(1.0, -1.0) * px).rgb);
  float sw = luma(texture(u_ldr, uv + vec2(-1.0, 1.0) * px).rgb);
  float se = luma(texture(u_ldr, uv + vec2(1.0, 1.0) * px).rgb);
  float m = luma(centre);
  float lo = min(m, min(min(nw, ne), min(sw, se)));
  float hi = max(m, max(max(nw, ne), max(sw, se)));
  // Across the edge's gradient: the direction along it.
  vec2 dir = vec2(-((nw + ne) - (sw + se)), (nw + sw) - (ne + se));
  float reduce = max((nw + ne + sw + se) * 0.25 * kReduceMul, kReduceMin);
  float scale = 1.0 / (min(abs(dir.x), abs(dir.y)) + reduce);
  dir = clamp(dir * scale, vec2(-kSpanMax), vec2(kSpanMax)) * px;
  vec3 a = 0.5 * (texture(u_ldr, uv + dir * (1.0 / 3.0 - 0.5)).rgb +
                  texture(u_ldr, uv + dir * (2.0 / 3.0 - 0.5)).rgb);
  vec3 b = 0.5 * a + 0.25 * (texture(u_ldr, uv - 0.5 * dir).rgb + texture(u_ldr, uv + 0.5 * dir).rgb);
  float lb = luma(b);
  // The wider blend unless it reaches past the neighbourhood's range.
  o_color = vec4(lb < lo || lb > hi ? a : b, 1.0);
}
