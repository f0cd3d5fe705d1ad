// Sunlight arriving at radius r: the transmittance to the top, or nothing
// when the planet stands between the point and the sun (its shadow;
// Hillaire 2020, sec. 5.2). By the including technique's
// transmittance_lookup(IN(Atmosphere), Real r, Real mu), declared before
// this file: a LUT on the GPU, a direct integral on the CPU.
Real3 sun_visibility(IN(Atmosphere) atmosphere, Real r, Real mu_s) {
  return ray_intersects_ground(atmosphere, r, mu_s) ? Real3(0.0)
                                                    : transmittance_lookup(atmosphere, r, mu_s);
}
