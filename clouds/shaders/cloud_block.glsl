// The shared cloud math in GLSL (Real = float; clouds/math/cloud_math.h
// compiles the same files in double) after the atmosphere's
// (atmosphere_block.glsl, whose phase functions the clouds' blend uses),
// and the layer's parameters as a uniform block mirrored by
// clouds/gpu/cloud_block.h.
#include "atmosphere/shaders/atmosphere_block.glsl"
#include "clouds/shaders/cloud_definitions.glsl"
#include "clouds/shaders/cloud_noise.glsl"
#include "clouds/shaders/cloud_density.glsl"
#include "clouds/shaders/cloud_phase.glsl"
#include "clouds/shaders/cloud_scattering.glsl"
