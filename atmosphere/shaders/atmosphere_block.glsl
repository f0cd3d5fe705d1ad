// The shared math in GLSL (Real = float; atmosphere/math/shared_math.h
// compiles the same files in double), and the atmosphere's parameters as a
// std140 uniform block, mirrored by atmosphere/gpu/atmosphere_block.h (whose
// static_asserts pin the layout) and unpacked into the shared Atmosphere
// struct.
#define Real float
#define Real3 vec3
#define Real2 vec2
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#include "atmosphere/shaders/definitions.glsl"
#include "atmosphere/shaders/lut_sizes.glsl"
#include "atmosphere/shaders/geometry.glsl"
#include "atmosphere/shaders/density.glsl"
#include "atmosphere/shaders/phase.glsl"
#include "atmosphere/shaders/lut_coordinates.glsl"
#include "atmosphere/shaders/transmittance.glsl"
#include "atmosphere/shaders/sun.glsl"
#include "atmosphere/shaders/occluded_sun.glsl"

layout(std140, binding = 0) uniform AtmosphereBlock {
  vec4 u_radii;  // bottom, top, mie g, sun angular radius
  vec4 u_solar_irradiance;
  vec4 u_rayleigh_scattering;
  vec4 u_mie_scattering;
  vec4 u_mie_extinction;
  vec4 u_absorption_extinction;
  vec4 u_ground_albedo;
  // Rayleigh, Mie, absorber; two layers each: (width, exp_term, exp_scale,
  // linear_term) and (constant_term, -, -, -).
  vec4 u_layer_a[6];
  vec4 u_layer_b[6];
};

DensityProfile block_profile(int i) {
  DensityProfile p;
  for (int k = 0; k < 2; ++k) {
    vec4 a = u_layer_a[2 * i + k];
    p.layers[k] = DensityLayer(a.x, a.y, a.z, a.w, u_layer_b[2 * i + k].x);
  }
  return p;
}

Atmosphere block_atmosphere() {
  Atmosphere a;
  a.bottom_radius = u_radii.x;
  a.top_radius = u_radii.y;
  a.solar_irradiance = u_solar_irradiance.rgb;
  a.sun_angular_radius = u_radii.w;
  a.rayleigh_scattering = u_rayleigh_scattering.rgb;
  a.rayleigh_density = block_profile(0);
  a.mie_scattering = u_mie_scattering.rgb;
  a.mie_extinction = u_mie_extinction.rgb;
  a.mie_g = u_radii.z;
  a.mie_density = block_profile(1);
  a.absorption_extinction = u_absorption_extinction.rgb;
  a.absorption_density = block_profile(2);
  a.ground_albedo = u_ground_albedo.rgb;
  a.mie_phase_hg = u_ground_albedo.w;
  return a;
}
