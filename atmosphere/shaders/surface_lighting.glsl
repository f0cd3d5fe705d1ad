// What the atmosphere gives a lit surface: the one file of the atmosphere
// that the terrain's shaders include (its CMake target,
// planet_atmosphere_surface_lighting, declares it; scripts/check-layers.sh
// keeps it so). Positions p and the sun's direction are in atmosphere space
// (atmosphere_space.h), irradiance per unit solar irradiance.
#include "atmosphere/shaders/atmosphere_block.glsl"

// The sun's zenith cosine at p.
float surface_mu_s(vec3 p, vec3 sun_dir) { return dot(p / length(p), sun_dir); }

// The sun's transmittance to p: nothing in the planet's shadow; 16
// quadrature steps, enough for a vertex.
vec3 surface_sun_transmittance(Atmosphere atmosphere, vec3 p, vec3 sun_dir) {
  float r = max(length(p), atmosphere.bottom_radius);
  float mu_s = surface_mu_s(p, sun_dir);
  return ray_intersects_ground(atmosphere, r, mu_s) ? vec3(0.0)
                                                    : transmittance_to_top(atmosphere, r, mu_s, 16);
}

// The share of the sky a surface with this normal sees: (1 + n.up) / 2.
float surface_sky_fraction(vec3 p, vec3 normal) {
  return 0.5 * (1.0 + dot(normalize(normal), p / length(p)));
}

// Sky irradiance, single scattering and isotropic: of the sunlight the beam
// loses on its way down to p (1 - T, scattering taken for all of the
// extinction), half goes down, spread over the sky; a horizontal surface
// receives mu_s of the beam's flux, a tilted one its sky fraction. A rough
// but documented ambient that vanishes at night and reddens with the sun
// (cf. Bruneton and Neyret 2008, eq. 15, for the full integral), for a
// technique that has no table of its own.
vec3 surface_sky_irradiance_estimate(vec3 p, vec3 normal, vec3 sun_dir, vec3 sun_transmittance) {
  return 0.5 * max(surface_mu_s(p, sun_dir), 0.0) * (vec3(1.0) - sun_transmittance) *
         surface_sky_fraction(p, normal);
}

// Better, where the technique has it (AtmosphereTechnique::ground_irradiance):
// the sky's irradiance on level ground summed over all orders of
// scattering, a one-row table over the sun's zenith cosine, times the same
// fraction.
vec3 surface_sky_irradiance(sampler2D table, vec3 p, vec3 normal, vec3 sun_dir) {
  float n = float(textureSize(table, 0).x);
  float u = texture_coord_from_unit_range(sky_irradiance_u_from_mu_s(surface_mu_s(p, sun_dir)), n);
  return texture(table, vec2(u, 0.5)).rgb * surface_sky_fraction(p, normal);
}
