// A switch of technique fading out: the previous technique's frame, laid
// over the new one's with blending at u_weight (its share of the pixel).
in vec2 v_ndc;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_previous;
uniform float u_weight;

void main() {
  o_color = vec4(texelFetch(u_previous, ivec2(gl_FragCoord.xy), 0).rgb, u_weight);
}
