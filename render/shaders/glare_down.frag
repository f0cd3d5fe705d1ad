// The glare's pyramid, down (render/glare.cpp): each level the one
// above at half its size, each texel the mean of a 4x4 block above it (four
// bilinear taps): every level keeps the image's energy.
in vec2 v_ndc;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_above;

void main() {
  vec2 texel = 1.0 / vec2(textureSize(u_above, 0));
  // The centre of the 2x2 block above this texel; each tap a 2x2 mean.
  vec2 uv = (2.0 * floor(gl_FragCoord.xy) + 1.0) * texel;
  vec3 sum = texture(u_above, uv + vec2(-texel.x, -texel.y)).rgb +
             texture(u_above, uv + vec2(texel.x, -texel.y)).rgb +
             texture(u_above, uv + vec2(-texel.x, texel.y)).rgb +
             texture(u_above, uv + vec2(texel.x, texel.y)).rgb;
  o_color = vec4(0.25 * sum, 1.0);
}
