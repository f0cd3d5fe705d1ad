// Phase functions, per steradian and integrating to 1 over the sphere, and
// the Legendre terms of Cornette-Shanks with which a technique scatters a
// field given by its spherical harmonics (the shared math: see
// definitions.glsl).
Real isotropic_phase() { return Real(1.0) / (Real(4.0) * kPi); }

// Rayleigh 1871: 3/(16 pi) (1 + nu^2).
Real rayleigh_phase(Real nu) { return Real(3.0) / (Real(16.0) * kPi) * (Real(1.0) + nu * nu); }

// Henyey and Greenstein 1941.
Real henyey_greenstein_phase(Real g, Real nu) {
  Real denom = Real(1.0) + g * g - Real(2.0) * g * nu;
  return (Real(1.0) - g * g) / (Real(4.0) * kPi * denom * sqrt(denom));
}

// Cornette and Shanks 1992: Henyey-Greenstein with a Rayleigh-like (1 + nu^2)
// factor, renormalised; the Mie phase of Bruneton 2017 and Hillaire 2020.
Real cornette_shanks_phase(Real g, Real nu) {
  Real k = Real(3.0) / (Real(8.0) * kPi) * (Real(1.0) - g * g) / (Real(2.0) + g * g);
  Real denom = Real(1.0) + g * g - Real(2.0) * g * nu;
  return k * (Real(1.0) + nu * nu) / (denom * sqrt(denom));
}

// The Legendre coefficient g_l of Cornette-Shanks (p = sum over l of
// (2l + 1) / (4 pi) g_l P_l). Cornette-Shanks is Henyey-Greenstein, whose
// coefficients are g^l, times 3 (1 + nu^2) / (2 (2 + g^2)), with
// 1 + nu^2 = 4/3 + (2/3) P_2 and
//   P_2 P_l = a P_(l+2) + b P_l + c P_(l-2),
//   a = 3 (l+1)(l+2) / (2 (2l+1)(2l+3)), b = l (l+1) / ((2l-1)(2l+3)),
//   c = 3 l (l-1) / (2 (2l-1)(2l+1)),
// so that the term l of P_2 times Henyey-Greenstein is
// a g^(l+2) + b g^l + c g^(l-2). g_0 = 1; g_1 = 3 g (4 + g^2) / (5 (2 + g^2)).
// cornette_shanks_term gives g_l for l >= 2 from g^(l-2), formed by
// products (g may be zero or negative), so that a series can carry it.
Real cornette_shanks_term(Real g, int l, Real g_l_minus_2) {
  Real x = Real(l);
  Real a = Real(3.0) * (x + Real(1.0)) * (x + Real(2.0)) /
           (Real(2.0) * (Real(2.0) * x + Real(1.0)) * (Real(2.0) * x + Real(3.0)));
  Real b = x * (x + Real(1.0)) / ((Real(2.0) * x - Real(1.0)) * (Real(2.0) * x + Real(3.0)));
  Real c = Real(3.0) * x * (x - Real(1.0)) /
           (Real(2.0) * (Real(2.0) * x - Real(1.0)) * (Real(2.0) * x + Real(1.0)));
  Real g_l = g_l_minus_2 * g * g;
  return Real(1.5) / (Real(2.0) + g * g) *
         (Real(4.0) / Real(3.0) * g_l +
          Real(2.0) / Real(3.0) * (a * g_l * g * g + b * g_l + c * g_l_minus_2));
}

Real cornette_shanks_legendre(Real g, int l) {
  if (l == 0) return Real(1.0);
  if (l == 1) return Real(3.0) * g * (Real(4.0) + g * g) / (Real(5.0) * (Real(2.0) + g * g));
  Real g_l_minus_2 = Real(1.0);
  for (int i = 2; i < l; ++i) g_l_minus_2 *= g;
  return cornette_shanks_term(g, l, g_l_minus_2);
}

// The aerosols' phase function as the model names it (Atmosphere's
// mie_phase_hg), and its Legendre coefficients: Henyey-Greenstein's are
// g^l.
Real mie_phase(IN(Atmosphere) atmosphere, Real nu) {
  return atmosphere.mie_phase_hg > Real(0.5) ? henyey_greenstein_phase(atmosphere.mie_g, nu)
                                             : cornette_shanks_phase(atmosphere.mie_g, nu);
}

Real mie_legendre(IN(Atmosphere) atmosphere, int l) {
  if (atmosphere.mie_phase_hg < Real(0.5)) return cornette_shanks_legendre(atmosphere.mie_g, l);
  Real g_l = Real(1.0);
  for (int i = 0; i < l; ++i) g_l *= atmosphere.mie_g;
  return g_l;
}

// The coefficient l >= 2 from g^(l-2), for a series that carries it:
// Cornette-Shanks's (cornette_shanks_term), or Henyey-Greenstein's g^l
// where hg is 1.
Real mie_series_term(Real hg, Real g, int l, Real g_l_minus_2) {
  return hg > Real(0.5) ? g_l_minus_2 * g * g : cornette_shanks_term(g, l, g_l_minus_2);
}
