// The glare's pyramid, up (render/glare.cpp): this level's own image
// plus the sum of the coarser levels, spread by a 3x3 tent (each coarser
// level is then one octave wider than the one above it).
in vec2 v_ndc;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_level;
layout(binding = 1) uniform sampler2D u_coarser;

void main() {
  vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_level, 0));
  vec2 t = 1.0 / vec2(textureSize(u_coarser, 0));
  vec3 tent = 4.0 * texture(u_coarser, uv).rgb;
  tent += 2.0 * (texture(u_coarser, uv + vec2(t.x, 0.0)).rgb +
                 texture(u_coarser, uv - vec2(t.x, 0.0)).rgb +
                 texture(u_coarser, uv + vec2(0.0, t.y)).rgb +
                 texture(u_coarser, uv - vec2(0.0, t.y)).rgb);
  tent += texture(u_coarser, uv + t).rgb + texture(u_coarser, uv - t).rgb +
          texture(u_coarser, uv + vec2(t.x, -t.y)).rgb +
          texture(u_coarser, uv + vec2(-t.x, t.y)).rgb;
  o_color = vec4(texelFetch(u_level, ivec2(gl_FragCoord.xy), 0).rgb + tent / 16.0, 1.0);
}
