// The least a full-screen pass can do: one constant into every pixel.
layout(location = 0) out vec4 o_color;

void main() { o_color = vec4(0.25, 0.5, 1.0, 1.0); }
