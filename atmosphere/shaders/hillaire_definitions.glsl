// Hillaire 2020's constants and the types its integrals share with their
// C++ side (atmosphere/math/hillaire_math.h); the functions are in
// hillaire_functions.glsl. The table sizes are in lut_sizes.glsl.
const int kTransmittanceSteps = 40;
// The parts of a multiple-scattering or order table, side by side along u:
// the field's spherical-harmonic coefficients up to degree kFieldDegree
// that the symmetry about the sun's vertical plane leaves (see
// FieldMoments), (L + 1)(L + 2) / 2 of them. Part 0 is the mean radiance.
// At Mars sunset the sun's glow crosses the dust near the ground sideways;
// to degree 2, the second order's irradiance on the ground came out
// 18-25 % above the path tracer's, to degree 4 within 3-9 %, to 6 and 8
// within 2-8 % (8 x 8 or 16 x 16 directions alike). But in the image,
// degree 6 with 8 azimuths a row made Mars sunset worse (19.0 / 12.9 /
// 6.8 % against 7.1 / 6.6 / 4.8 %): the gather cannot resolve it.
// field_basis is written out to degree 4.
const int kFieldDegree = 4;
const int kFieldParts = (kFieldDegree + 1) * (kFieldDegree + 2) / 2;
const int kFieldMean = 0;
// Orders of scattering summed explicitly before the geometric tail. The
// ratio of successive orders still falls after the fourth in thick dust
// (Mars sunset, red: 0.78, 0.66, 0.62, 0.61 from the fourth to the
// eighth), and a tail from 4 orders made the red sky 2x too bright beyond
// them; from 6 orders the tail is within 3 % of orders 7 and up.
const int kScatteringOrders = 6;
// The orders gathered on the multiple-scattering LUT's own grid; the later
// ones, which every order before has smoothed, on kCoarseOrderWidth x
// kCoarseOrderHeight texels (lut_sizes.glsl), read by the next order and
// the sum between their texels: a model change 1.4-2.2x cheaper. The
// second order still needs the planet shadow's edge along mu_s (on the
// coarse grid, twilight's blue sky went from 2.6 to 5.7 % off).
const int kFineScatteringOrders = 2;
// 8 x 8 stratified directions over the sphere (Hillaire 2020, sec. 5.5: 64).
const int kMultipleScatteringDirectionsSqrt = 8;
// Segments per gathered ray: from 20 to 12 no canonical sky moved by more
// than 0.15 % (worst-channel relative RMSE), at 0.67 of the cost.
const int kMultipleScatteringSteps = 12;
// The Legendre terms the forward-gain LUT sums (g_64 of g = 0.8 is 6e-7).
const int kForwardGainTerms = 64;

// What lights the air along a ray:
// - kSourceSky: the sun with the true phase functions and the glow's
//   forward gain, plus every higher order from the multiple-scattering LUT
//   (Hillaire 2020, eq. 11);
// - kSourceFirstOrder: the sun with the true phase functions alone
//   (gather_order splits it into the two kinds below);
// - kSourceIsotropicSun: the sun with the isotropic phase (the paper's
//   L_2 pass, sec. 5.5);
// - kSourceNextOrder: the previous order's light (scattering_order_lookup)
//   scattered once more; the ground reflects E_n.
const int kSourceSky = 0;
const int kSourceFirstOrder = 1;
const int kSourceIsotropicSun = 2;
const int kSourceNextOrder = 3;
// The first order in two parts, which gather_order sums (see there):
// - kSourceSunRayleigh: the sun scattered by Rayleigh alone, and the lit
//   ground;
// - kSourceSunMie: the sun scattered by Mie with a phase of 1 (the phase
//   is carried by the directions' distribution), without the ground.
const int kSourceSunRayleigh = 4;
const int kSourceSunMie = 5;

// Where integrate_along reads the field along a ray (see there).
const int kFieldEachStep = 0;
const int kFieldPerPair = 1;
const int kFieldInterpolated = 2;

// The light of an order (or of all higher orders) arriving at a point, as
// its spherical-harmonic coefficients over the sphere of directions w
// looked along, in the local frame of the zenith (z), the sun's horizontal
// direction (x) and the direction across it (y). The field is symmetric
// about the sun's vertical plane (y -> -y), which leaves the terms
// cos(m phi) of each degree l: part l (l + 1) / 2 + m for 0 <= m <= l.
// The basis is orthonormal in the mean over the sphere, with B_00 = 1, and
// the sum over m of B_lm(w) B_lm(d) is (2l + 1) times the mean of P_l(w.d)
// over w and its mirror image (the addition theorem, less the sin(m phi)
// terms, which cancel over an even field). Part (l, m) holds the mean over
// the sphere of L B_lm; part 0 is the mean radiance.
struct FieldMoments {
  Real3 part[kFieldParts];
};
