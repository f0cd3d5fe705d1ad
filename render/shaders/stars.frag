// A star's radiance, added where no surface was drawn.
in vec3 v_radiance;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_depth;  // reversed Z: 0 where no surface is

void main() {
  if (texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r > 0.0) discard;
  o_color = vec4(v_radiance, 0.0);
}
