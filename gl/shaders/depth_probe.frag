// DepthProbe's pass: every pixel at one depth, tested against the stored
// depth and counted; nothing is written.
uniform float u_depth;

void main() { gl_FragDepth = u_depth; }
