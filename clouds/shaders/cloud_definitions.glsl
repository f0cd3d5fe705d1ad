// The cloud layer as the shared cloud math sees it, written once in the
// common subset of GLSL and C++-with-GLM like atmosphere/shaders (see
// definitions.glsl there): shaders #include it with Real = float
// (clouds/shaders/cloud_block.glsl), clouds/math/cloud_math.h with Real =
// double, so that the path tracer, the tests and the GPU pass see the same
// cloud. Lengths in metres, radii from the planet's centre.
struct CloudLayer {
  Real bottom_radius;  // the layer's base
  Real top_radius;     // its top
  // The weather's cover, 0 clear to 1 overcast (about the sky's cloud
  // fraction), and the share of cumulus in it (the rest stratus).
  Real coverage;
  Real cumulus_share;
  // The noises' cells: the weather (cover and type over the globe), the
  // clouds' shapes and the erosion of their edges; erosion 0 keeps the
  // shapes whole, 1 eats them away.
  Real weather_scale;
  Real shape_scale;
  Real erosion_scale;
  Real erosion;
  // The droplets: extinction at density 1 (1/m), single-scattering albedo
  // and effective diameter (micrometres) for the phase function.
  Real extinction;
  Real albedo;
  Real droplet_diameter_um;
  // Shifts the noises' lattice: a whole number below 2^24 (exact in float).
  Real seed;
};
