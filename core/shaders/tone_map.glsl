// The tone map from linear radiance times exposure to sRGB-encoded colour,
// in the common subset of GLSL and C++-with-GLM: render/shaders/
// tonemap.frag compiles it with Real = float for every frame, core/
// tone_map.cpp with Real = double for the PNGs beside the ground truth, so
// that both are one curve. The includer defines Real and Real3.

// Narkowicz's 2015 fit of the ACES filmic curve.
Real3 aces_fit(Real3 x) {
  return clamp((x * (Real(2.51) * x + Real(0.03))) / (x * (Real(2.43) * x + Real(0.59)) + Real(0.14)),
               Real(0.0), Real(1.0));
}

// The sRGB transfer function (IEC 61966-2-1).
Real3 srgb_encode(Real3 c) {
  return mix(Real(12.92) * c, Real(1.055) * pow(c, Real3(Real(1.0) / Real(2.4))) - Real(0.055),
             step(Real(0.0031308), c));
}

Real3 tone_map(Real3 exposed) { return srgb_encode(aces_fit(exposed)); }
