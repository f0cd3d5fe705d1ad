// The clouds at full resolution over the frame's radiance: their rgb
// added, their alpha (transmittance) the blend's factor for what is behind
// (GL_ONE, GL_SRC_ALPHA).
layout(binding = 0) uniform sampler2D u_clouds;
layout(location = 0) out vec4 o_radiance;

void main() { o_radiance = texelFetch(u_clouds, ivec2(gl_FragCoord.xy), 0); }
