// How regolith reflects sunlight: Hapke's bidirectional reflectance with
// the shadow-hiding opposition surge and macroscopic roughness, written
// once in the common subset of GLSL and C++-with-GLM: terrain.frag
// includes it with Real = float, terrain/regolith.cpp with Real = double,
// so that the frame and the CPU's phase curve read the very same law. The
// including side defines Real and kPi. Angles in radians.
//
// Hapke 1981 (JGR 86, 3039), 1984 (Icarus 59, 41) and 1986 (Icarus 67,
// 264), as gathered in Hapke 1993, "Theory of reflectance and emittance
// spectroscopy", chapters 8 and 12: the bidirectional reflectance
//   r = w / (4 pi) mu0e / (mu0e + mue) [(1 + B(g)) P(g) + H(mu0e) H(mue) - 1] S
// (the radiance over the irradiance on a plane facing the sun; Lambert's
// is A mu0 / pi), with
//   B(g) = B0 / (1 + tan(g / 2) / h)        the opposition surge,
//   P(g)                                      the grains' phase function
//                                             (Henyey-Greenstein, xi < 0 backward),
//   H(x)                                      Chandrasekhar's, Hapke 2002's approximation,
//   mu0e, mue, S                              the rough surface's effective cosines and
//                                             shadowing, for a mean slope theta_bar.
// Unlike Lambert's, r stays near its centre's value toward the limb of a
// full disk (mu0e / (mu0e + mue) is 1/2 wherever i = e), and falls to zero
// at the terminator faster than mu0 (S).
struct RegolithLaw {
  Real w;          // single-scattering albedo
  Real xi;         // Henyey-Greenstein asymmetry of the grains (negative: backward)
  Real b0;         // the opposition surge's amplitude
  Real h;          // its angular width
  Real theta_bar;  // the mean slope of the roughness below a pixel, radians
};

// Hapke 2002 (Icarus 157, 523): Chandrasekhar's H function of
// isotropic scatterers to within 1 %.
Real regolith_h(Real w, Real x) {
  x = max(x, Real(1e-6));  // x ln((1 + x) / x) -> 0
  Real gamma = sqrt(Real(1.0) - w);
  Real r0 = (Real(1.0) - gamma) / (Real(1.0) + gamma);
  return Real(1.0) /
         (Real(1.0) - w * x * (r0 + (Real(1.0) - Real(2.0) * r0 * x) * Real(0.5) *
                                        log((Real(1.0) + x) / x)));
}

// Hapke 1984: the terms of the roughness at an angle x
// (incidence or emission) for tan(theta_bar) = t; x away from 0, where the
// cotangent has no limit the exponentials need (they tend to 0).
Real regolith_e1(Real t, Real x) {
  return exp(Real(-2.0) / kPi / (t * tan(max(x, Real(1e-4)))));
}
Real regolith_e2(Real t, Real x) {
  Real c = Real(1.0) / (t * tan(max(x, Real(1e-4))));
  return exp(-c * c / kPi);
}
// Hapke 1984 (eta): a cosine's effective value on the rough
// surface when the other ray lies on the normal.
Real regolith_eta(Real t, Real chi, Real x) {
  return chi * (cos(x) + sin(x) * t * regolith_e2(t, x) / (Real(2.0) - regolith_e1(t, x)));
}

// The bidirectional reflectance r of regolith lit at incidence cosine mu0
// and seen at emission cosine mu, with cos_g the cosine of the phase angle
// (between the directions to the sun and to the eye). Zero where the sun
// is below the facet; a facet seen beyond its horizon (a normal
// interpolated over a silhouette) is seen at grazing emission.
Real regolith_reflectance(RegolithLaw law, Real mu0, Real mu, Real cos_g) {
  if (mu0 <= Real(0.0)) return Real(0.0);
  mu0 = min(mu0, Real(1.0));
  mu = clamp(mu, Real(1e-4), Real(1.0));
  cos_g = clamp(cos_g, Real(-1.0), Real(1.0));
  // The opposition surge (Hapke 1986); tan(g / 2) = sin g / (1 + cos g).
  Real tan_half_g = sqrt(max(Real(1.0) - cos_g, Real(0.0)) / max(Real(1.0) + cos_g, Real(1e-6)));
  Real surge = law.b0 / (Real(1.0) + tan_half_g / law.h);
  Real xi = law.xi;
  Real hg_denom = Real(1.0) + Real(2.0) * xi * cos_g + xi * xi;
  Real p = (Real(1.0) - xi * xi) / (hg_denom * sqrt(hg_denom));
  Real mu0e = mu0, mue = mu, shadowing = Real(1.0);
  if (law.theta_bar > Real(1e-4)) {
    // Hapke 1984, for i <= e and for e < i, psi the azimuth
    // between the planes of incidence and emission.
    Real t = tan(law.theta_bar);
    Real chi = Real(1.0) / sqrt(Real(1.0) + kPi * t * t);
    Real i = acos(mu0), e = acos(mu);
    Real sin_i = sin(i), sin_e = sin(e);
    Real cos_psi = sin_i * sin_e > Real(1e-6) ? (cos_g - mu0 * mu) / (sin_i * sin_e) : Real(1.0);
    Real psi = acos(clamp(cos_psi, Real(-1.0), Real(1.0)));
    Real sin2_half_psi = Real(0.5) * (Real(1.0) - cos(psi));
    Real f = exp(Real(-2.0) * tan(min(Real(0.5) * psi, Real(1.5707))));
    Real e1_i = regolith_e1(t, i), e2_i = regolith_e2(t, i);
    Real e1_e = regolith_e1(t, e), e2_e = regolith_e2(t, e);
    Real eta_i = regolith_eta(t, chi, i), eta_e = regolith_eta(t, chi, e);
    if (i <= e) {
      Real d = Real(2.0) - e1_e - psi / kPi * e1_i;
      mu0e = chi * (mu0 + sin_i * t * (cos(psi) * e2_e + sin2_half_psi * e2_i) / d);
      mue = chi * (mu + sin_e * t * (e2_e - sin2_half_psi * e2_i) / d);
      shadowing = mue / eta_e * mu0 / eta_i * chi /
                  (Real(1.0) - f + f * chi * mu0 / eta_i);
    } else {
      Real d = Real(2.0) - e1_i - psi / kPi * e1_e;
      mu0e = chi * (mu0 + sin_i * t * (e2_i - sin2_half_psi * e2_e) / d);
      mue = chi * (mu + sin_e * t * (cos(psi) * e2_i + sin2_half_psi * e2_e) / d);
      shadowing = mue / eta_e * mu0 / eta_i * chi / (Real(1.0) - f + f * chi * mu / eta_e);
    }
    mu0e = max(mu0e, Real(0.0));
    mue = max(mue, Real(1e-6));
  }
  Real multiple = regolith_h(law.w, mu0e) * regolith_h(law.w, mue) - Real(1.0);
  return law.w / (Real(4.0) * kPi) * mu0e / (mu0e + mue) *
         ((Real(1.0) + surge) * p + multiple) * shadowing;
}
