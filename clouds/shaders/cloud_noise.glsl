// Arithmetic noise for the clouds (the shared cloud math, see
// cloud_definitions.glsl): an integer hash of the lattice point, so that the
// GPU and the CPU build the same field without a noise texture. Unsigned
// 32-bit arithmetic wraps alike in GLSL and C++; the lattice cell comes from
// floor() of a position in float on the GPU and double on the CPU, and the
// noise is continuous across cells, so a point a hair from a cell's face
// gives the same value on either side.

// Jarzynski and Olano 2020, "Hash Functions for GPU Rendering": pcg3d.
uint cloud_hash(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v.x ^ v.y ^ v.z;
}

// The hash's top 24 bits as a number in [0, 1), exact in float and double.
Real cloud_lattice_value(ivec3 cell, uint seed) {
  uint h = cloud_hash(uvec3(cell) + uvec3(seed, seed * 7u, seed * 13u));
  return Real(h >> 8u) * Real(1.0 / 16777216.0);
}

// Value noise in [0, 1): the lattice values blended with a smoothstep, C1
// across the cells' faces.
Real cloud_value_noise(Real3 p, uint seed) {
  Real3 cell = floor(p);
  Real3 f = p - cell;
  Real3 u = f * f * (Real(3.0) - Real(2.0) * f);
  ivec3 c = ivec3(cell);
  Real n000 = cloud_lattice_value(c, seed);
  Real n100 = cloud_lattice_value(c + ivec3(1, 0, 0), seed);
  Real n010 = cloud_lattice_value(c + ivec3(0, 1, 0), seed);
  Real n110 = cloud_lattice_value(c + ivec3(1, 1, 0), seed);
  Real n001 = cloud_lattice_value(c + ivec3(0, 0, 1), seed);
  Real n101 = cloud_lattice_value(c + ivec3(1, 0, 1), seed);
  Real n011 = cloud_lattice_value(c + ivec3(0, 1, 1), seed);
  Real n111 = cloud_lattice_value(c + ivec3(1, 1, 1), seed);
  Real x00 = mix(n000, n100, u.x);
  Real x10 = mix(n010, n110, u.x);
  Real x01 = mix(n001, n101, u.x);
  Real x11 = mix(n011, n111, u.x);
  return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

// Fractal sum of `octaves` value noises, each twice the frequency and half
// the weight of the last, normalised to [0, 1). The octaves' lattices are
// rotated apart by an odd offset so that their cell faces do not line up.
Real cloud_fbm(Real3 p, uint seed, int octaves) {
  Real sum = Real(0.0);
  Real weight = Real(0.5);
  Real total = Real(0.0);
  for (int i = 0; i < octaves; ++i) {
    sum += weight * cloud_value_noise(p, seed + uint(i) * 101u);
    total += weight;
    weight *= Real(0.5);
    p = p * Real(2.0) + Real3(0.37, 0.71, 0.13);
  }
  return sum / total;
}
