// The open sea's reflection, written once in the common subset of GLSL and
// C++-with-GLM (as atmosphere/shaders/definitions.glsl is): terrain.frag
// includes it with Real = float, terrain/sea_brdf.cpp compiles it in
// double, so that the tests integrate the very BRDF the GPU draws. The
// including side defines Real and Real3 (and kPi).
//
// The sea is a rough dielectric: the Fresnel reflectance of water, and
// facets whose slopes follow Cox and Munk's (1954) Gaussian; see
// docs/sea.md.

// Sea water's index of refraction in the visible (about 1.33 for pure
// water, plus about 0.006 for salt).
const Real kSeaIndex = 1.34;

// The unpolarised Fresnel reflectance of the sea for light arriving at
// cos_i to the facet's normal (Born and Wolf's form with
// g = sqrt(n^2 - 1 + c^2)): 0.021 at normal incidence, 1 at grazing.
Real sea_fresnel(Real cos_i) {
  Real c = clamp(cos_i, Real(0.0), Real(1.0));
  Real g = sqrt(kSeaIndex * kSeaIndex - Real(1.0) + c * c);
  Real a = (g - c) / (g + c);
  Real b = (c * (g + c) - Real(1.0)) / (c * (g - c) + Real(1.0));
  return Real(0.5) * a * a * (Real(1.0) + b * b);
}

// Cox and Munk 1954 (J. Opt. Soc. Am. 44, 838; their fit over a clean
// sea): the mean square slope of the sea, both directions together, for a
// wind of wind_m_s measured 12.5 m above it: 0.003 + 5.12e-3 U (+- 0.004).
Real cox_munk_slope_variance(Real wind_m_s) { return Real(0.003) + Real(5.12e-3) * wind_m_s; }

// Their distribution of slopes, isotropic (no up- and cross-wind split, no
// skewness): p(zx, zy) = exp(-(zx^2 + zy^2) / s2) / (pi s2), of
// tan^2(beta) = zx^2 + zy^2 with beta the facet's tilt.
Real cox_munk_slope_pdf(Real tan2_beta, Real sigma2) {
  return exp(-tan2_beta / sigma2) / (kPi * sigma2);
}

// The sun's glint: the radiance the sea sends toward `view` per unit of
// the sun's irradiance (normal to its beam) arriving from `sun`, over a sea
// whose mean surface has the normal `n` (all unit vectors away from the
// surface). The microfacet form without shadowing, as Cox and Munk reduced
// their photographs of the glitter: the facets that mirror the sun
// into the view have the half vector h as normal, their slope density is
// p / cos^4(beta) per unit solid angle of h, and
//   L / E = F(h.sun) p(tan^2 beta) / (4 cos_view cos^4 beta).
// Zero where the sun or the view lies below the mean surface.
Real sea_glint(Real3 n, Real3 view, Real3 sun, Real sigma2) {
  Real cos_view = dot(n, view);
  Real cos_sun = dot(n, sun);
  if (cos_view <= Real(0.0) || cos_sun <= Real(0.0)) return Real(0.0);
  Real3 h = normalize(view + sun);
  Real cos_beta = dot(n, h);
  Real cos2 = cos_beta * cos_beta;
  Real tan2 = (Real(1.0) - cos2) / cos2;
  return sea_fresnel(dot(h, sun)) * cox_munk_slope_pdf(tan2, sigma2) /
         (Real(4.0) * cos_view * cos2 * cos2);
}
