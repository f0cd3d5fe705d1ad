// A star's radiance, added where no surface was drawn, through the
// clouds' transmittance where the frame has clouds.
in vec3 v_radiance;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_depth;   // reversed Z: 0 where no surface is
layout(binding = 1) uniform sampler2D u_clouds;  // alpha: the clouds' transmittance
uniform int u_has_clouds;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(u_depth, pixel, 0).r > 0.0) discard;
  float clouds = u_has_clouds != 0 ? texelFetch(u_clouds, pixel, 0).a : 1.0;
  o_color = vec4(v_radiance * clouds, 0.0);
}
