// The atmosphere as the shared math sees it, written once in the common
// subset of GLSL and C++-with-GLM: shaders #include it with Real = float
// (atmosphere_block.glsl), and atmosphere/math/shared_math.h with Real =
// double, so that the ground truth, the tests and every technique read the
// very same model. The including side defines Real, Real2, Real3, IN(T),
// OUT(T) and INOUT(T).
//
// Conventions (Bruneton 2017): r is the distance from the planet's centre,
// mu the cosine of the view zenith angle, mu_s that of the sun zenith angle,
// nu the cosine of the angle between view and sun. Lengths in metres.
//
// Bruneton 2017's layer: density(h) = clamp(exp_term * exp(exp_scale * h)
// + linear_term * h + constant_term, 0, 1) for h below `width` (the last
// layer extends to the top). Exponential, linear and tent profiles are all
// one or two such layers. Widths in metres, scales in 1/m.
struct DensityLayer {
  Real width;
  Real exp_term;
  Real exp_scale;
  Real linear_term;
  Real constant_term;
};

struct DensityProfile {
  DensityLayer layers[2];
};

struct Atmosphere {
  Real bottom_radius;
  Real top_radius;
  Real3 solar_irradiance;
  Real sun_angular_radius;
  Real3 rayleigh_scattering;
  DensityProfile rayleigh_density;
  Real3 mie_scattering;
  Real3 mie_extinction;
  Real mie_g;
  DensityProfile mie_density;
  Real3 absorption_extinction;
  DensityProfile absorption_density;
  Real3 ground_albedo;
  // The aerosols' phase function (MiePhase): 0 Cornette-Shanks, 1
  // Henyey-Greenstein.
  Real mie_phase_hg;
};

const Real kPi = 3.14159265358979323846;
