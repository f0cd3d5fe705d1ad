// The exposure that puts the frame's mean luminance at a middle grey: one
// work group walks every second pixel each way in a fixed order and sums
// in a fixed tree, so the same frame gives the same exposure on every run.
// Each pixel's luminance is capped (the sun's disc and its glare would set
// the exposure alone otherwise), and the exposure is bounded: at its
// highest, that of an eye adapted to a dark night.
layout(local_size_x = 256) in;

layout(binding = 0) uniform sampler2D u_hdr;
layout(std430, binding = 3) buffer ExposureBlock {
  float exposure;
  float mean_luminance;
};
uniform ivec2 u_size;
uniform float u_key;       // the mean luminance's value after exposure
uniform float u_cap;       // the most a pixel counts for
uniform vec2 u_bounds;     // the least and most exposure

shared float partial[256];

void main() {
  uint i = gl_LocalInvocationIndex;
  int columns = (u_size.x + 1) / 2, rows = (u_size.y + 1) / 2;
  int n = columns * rows;
  float sum = 0.0;
  for (int k = int(i); k < n; k += 256) {
    vec3 c = texelFetch(u_hdr, 2 * ivec2(k % columns, k / columns), 0).rgb;
    sum += min(max(dot(c, vec3(0.2126, 0.7152, 0.0722)), 0.0), u_cap);
  }
  partial[i] = sum;
  barrier();
  for (uint s = 128u; s > 0u; s >>= 1) {
    if (i < s) partial[i] += partial[i + s];
    barrier();
  }
  if (i == 0u) {
    float mean = partial[0] / float(n);
    mean_luminance = mean;
    exposure = clamp(u_key / max(mean, 1e-30), u_bounds.x, u_bounds.y);
  }
}
