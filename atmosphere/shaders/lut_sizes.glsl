// The sizes of the lookup tables, in texels, in one place: the techniques'
// shaders and their C++ sides (atmosphere/math/shared_math.h) read them here.
// Hillaire 2020 and Bruneton 2017 store the transmittance alike.
const int kTransmittanceLutWidth = 256;
const int kTransmittanceLutHeight = 64;
// The multiple-scattering LUT: sun zenith (u) by altitude (v). Twilight
// needs texels along mu_s, where the planet's shadow has a sharp edge: 5
// deg after sunset the ground's sky light came out 6-12 % too high with 64
// and within 3 % with 128 (the sky: 6.6 and 4.7 % worst channel). The
// ground's sky-irradiance table has its width, over the same mu_s.
const int kMultipleScatteringLutWidth = 128;
const int kMultipleScatteringLutHeight = 32;
// The orders of scattering past kFineScatteringOrders
// (hillaire_definitions.glsl) over the same (mu_s, r), on a coarser grid:
// coarser along mu_s alone, since near the ground the light changes
// within a few kilometres (with 8 rows the tenfold-dense Earth's blue sky
// went from 4.9 to 45 % off).
const int kCoarseOrderWidth = 32;
const int kCoarseOrderHeight = 32;
// The forward-gain LUT: nu (u) by Mie scattering optical depth (v).
const int kForwardGainLutWidth = 256;
const int kForwardGainLutHeight = 64;
const int kSkyViewLutWidth = 200;
const int kSkyViewLutHeight = 100;
const int kAerialPerspectiveSize = 32;
// hillaire's space-view LUT (space_view_lut.glsl): the azimuth from the
// sun's by the ray's distance from the planet's centre, and for the air in
// front of surfaces, by the altitude the ray has come down to, in slices
// over the ground's range of heights (on Mars, 32 of them left the view
// from 400 km 1.3 % off the march, 64 0.45 %), marched down to from the
// top in kSpaceViewUpperSegments.
const int kSpaceViewLutWidth = 64;
const int kSpaceViewLutHeight = 128;
const int kSpaceViewLutDepth = 64;
const int kSpaceViewUpperSegments = 16;
