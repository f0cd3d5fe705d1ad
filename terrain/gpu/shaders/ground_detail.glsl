// The ground's procedural detail below what the tiles and the day image
// resolve: value noise in the body frame (no texture, so no tiling), as an
// albedo factor and a perturbation of the normal. Grain: the four octaves
// just coarser than the pixel's footprint on the ground, so that the ground
// has texture near the camera: the two octaves just coarser than the
// pixel's footprint on the ground, within 2 km of the eye (farther, the
// vertices' fields carry the ground). Each octave fades in as its
// wavelength grows from 2 to 4 footprints and out from 4 to 8, so that
// nothing finer than two pixels is summed (no shimmer) and no octave pops
// as the camera moves. (The fields of light and shade, 0.5 to 8 km, the tiles'
// vertices carry: the palette's variation, surface_color.h.) See
// docs/surfaces.md#detail.
//
// Precision: a body-frame position in float is 0.5 m coarse on Earth, too
// coarse for the 0.5 m octave. The tile gives its centre in units of the
// finest wavelength split on the CPU, in double, into an integer cell and
// a fraction; the fragment adds its offset from the centre, small and
// exact, and each octave's cell is the centre's cell shifted right.

uniform ivec3 u_detail_cell;  // floor(tile centre / kDetailFinest)
uniform vec3 u_detail_frac;   // tile centre / kDetailFinest - u_detail_cell
const float kDetailFinest = 0.5;  // metres: the finest octave's wavelength (terrain_renderer.cpp)

// A lattice point's value in [-1, 1]: the coordinates' products with odd
// constants, XORed (each corner of a cell then costs two XORs, not a hash
// of three), through one round of a multiply-xorshift finaliser (the first
// of Wellons's lowbias32, 2018, "Prospecting for hash functions"): a
// software rasteriser pays for every instruction of every pixel.
float detail_hash(uint h) {
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  return float(h) * (2.0 / 4294967296.0) - 1.0;
}

// Value noise with its gradient (Quilez's analytic derivatives of the
// quintic fade): .x the value in [-1, 1], .yzw its gradient over f.
vec4 detail_noise(ivec3 cell, vec3 f) {
  vec3 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  vec3 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
  const uvec3 kOdd = uvec3(0x8da6b343u, 0xd8163841u, 0xcb1ab31fu);
  uvec3 p0 = uvec3(cell) * kOdd, p1 = p0 + kOdd;
  float a = detail_hash(p0.x ^ p0.y ^ p0.z);
  float b = detail_hash(p1.x ^ p0.y ^ p0.z);
  float c = detail_hash(p0.x ^ p1.y ^ p0.z);
  float d = detail_hash(p1.x ^ p1.y ^ p0.z);
  float e = detail_hash(p0.x ^ p0.y ^ p1.z);
  float g = detail_hash(p1.x ^ p0.y ^ p1.z);
  float h = detail_hash(p0.x ^ p1.y ^ p1.z);
  float k = detail_hash(p1.x ^ p1.y ^ p1.z);
  float k1 = b - a, k2 = c - a, k3 = e - a, k4 = a - b - c + d;
  float k5 = a - c - e + h, k6 = a - b - e + g, k7 = -a + b + c - d + e - g - h + k;
  float value = a + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z +
                k6 * u.z * u.x + k7 * u.x * u.y * u.z;
  vec3 grad = du * vec3(k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z,
                        k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x,
                        k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y);
  return vec4(value, grad);
}

// Octave `k` (wavelength kDetailFinest 2^k) at `offset` from the tile's
// centre: the noise and its gradient per metre.
vec4 detail_octave(int k, vec3 offset) {
  ivec3 mask = ivec3((1 << k) - 1);
  vec3 local = (vec3(u_detail_cell & mask) + u_detail_frac + offset / kDetailFinest) *
               exp2(-float(k));
  vec3 cell = floor(local);
  vec4 n = detail_noise((u_detail_cell >> k) + ivec3(cell) + ivec3(7919 * k), local - cell);
  return vec4(n.x, n.yzw / (kDetailFinest * exp2(float(k))));
}

// .x the albedo's factor (mean 1), .yzw the gradient of the detail's
// height field, to tilt the normal by. `offset`: from the tile's centre,
// metres; `footprint`: a pixel on the ground, metres.
vec4 ground_detail(vec3 offset, float footprint) {
  float grain = 0.0;
  vec3 slope = vec3(0.0);
  // Grain: octaves from 2 to 8 footprints; slopes of 0.07 per octave.
  // Near the camera, where the pixel is finer than the finest octave, the
  // grain keeps its two finest (0.5 and 1 m).
  float coarsest = 8.0 * max(footprint, 0.5 * kDetailFinest);
  int k0 = clamp(int(ceil(log2(max(2.0 * footprint / kDetailFinest, 1.0)))), 0, 24);
  for (int k = k0; k < k0 + 2; ++k) {
    float w = kDetailFinest * exp2(float(k));
    float weight = smoothstep(2.0 * footprint, 4.0 * footprint, w) *
                   (1.0 - smoothstep(0.5 * coarsest, coarsest, w));
    if (weight <= 0.0) continue;
    vec4 n = detail_octave(k, offset);
    grain += weight * n.x;
    slope += weight * 0.07 * n.yzw * w;
  }
  // Value noise stays mostly within +-0.6: the grain +-15 %.
  float factor = 1.0 + 0.25 * clamp(0.7 * grain, -1.0, 1.0);
  return vec4(factor, slope);
}
