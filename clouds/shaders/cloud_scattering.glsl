// The light a cloud scatters toward the camera, single and multiple (the
// shared cloud math, see cloud_definitions.glsl). Needs isotropic_phase
// from atmosphere/shaders/phase.glsl.

// Wrenninge et al. 2013's octaves ("Production Volume Rendering", SIGGRAPH
// course, sec. 5.4): octave k takes a^k of the optical depth toward the
// sun, b^k of the light and a phase c^k as eccentric (a blend of `phase`
// toward isotropic). Per unit of the sun's irradiance at the point and of
// the droplets' single-scattering albedo, per steradian.
//
// Octave 0 is the sun's light scattered once. The others stand for light
// that has entered the clouds and scattered on: into a deck it comes
// through the top, mu_s of the sun's irradiance per unit area, and the
// share a thick deck sends back up rises as the sun lowers (the light goes
// in less deep): the delta-Eddington albedo (conservative; Joseph,
// Wiscombe and Weinman 1976) of a deck of optical depth 10, Earth's
// overcast, is 0.62, 0.51 and 0.39 at mu_s 0.3, 0.574 and 0.9, about as
// 1 / sqrt(mu_s), where the octaves with all of the irradiance go as
// 1 / mu_s, and with Wrenninge's b = 1/2 reflected 0.28 at mu_s 0.574
// whatever the deck's depth past 5. So the octaves past the first carry
// sqrt(mu_s) of the light (mu_s at least 0.04: a cumulus as tall as it is
// wide takes a low sun on its side) with b = 0.7 (within Wrenninge's
// a <= b, which keeps energy): at optical depth 10 a deck's albedo is then
// 0.90 to 1.02 of delta-Eddington's; a thicker deck's is too low, 0.64 to
// 0.85 of it at 20 and 0.50 to 0.75 at 40, for the octaves' albedo does
// not grow with the deck's depth (CloudScatteringTest.OctavesReflectAsAnEddingtonDeckDoes,
// docs/clouds.md#brightness).
Real cloud_octaves(Real phase, Real tau_sun, Real mu_s, int octaves) {
  Real single = phase * exp(-tau_sun);
  Real multiple = Real(0.0);
  Real a = Real(1.0), b = Real(1.0), c = Real(1.0);
  for (int k = 1; k < octaves; ++k) {
    a *= Real(0.25);
    b *= Real(0.7);
    c *= Real(0.5);
    multiple += b * mix(isotropic_phase(), phase, c) * exp(-a * tau_sun);
  }
  return single + sqrt(max(mu_s, Real(0.04))) * multiple;
}
