#pragma once
// The shared math (atmosphere/shaders/*.glsl, see definitions.glsl) as C++
// in double, compiled once in shared_math.cpp as Bruneton's reference
// implementation compiles its functions.glsl: the ground truth and the
// tests run the very same formulas as the GPU. These are the files'
// functions, declared in their order; a signature that differs from its
// GLSL definition fails to link.
#include "atmosphere/math/definitions.h"
#include "atmosphere/model.h"

namespace planet::shared {

// geometry.glsl
Real clamp_cosine(Real mu);
Real safe_sqrt(Real a);
bool ray_sphere(const Real3& o, const Real3& d, Real R, Real& t_near, Real& t_far);
Real distance_to_top_boundary(const Atmosphere& atmosphere, Real r, Real mu);
Real distance_to_bottom_boundary(const Atmosphere& atmosphere, Real r, Real mu);
bool ray_intersects_ground(const Atmosphere& atmosphere, Real r, Real mu);
bool ray_shell(const Real3& o, const Real3& d, Real r_inner, Real r_outer, Real& t_enter,
               Real& t_exit);

// density.glsl
Real layer_density(const DensityLayer& layer, Real altitude);
Real profile_density(const DensityProfile& profile, Real altitude);
Real3 extinction_at(const Atmosphere& atmosphere, Real altitude);

// phase.glsl
Real isotropic_phase();
Real rayleigh_phase(Real nu);
Real henyey_greenstein_phase(Real g, Real nu);
Real cornette_shanks_phase(Real g, Real nu);
Real cornette_shanks_term(Real g, int l, Real g_l_minus_2);
Real cornette_shanks_legendre(Real g, int l);
Real mie_phase(const Atmosphere& atmosphere, Real nu);
Real mie_legendre(const Atmosphere& atmosphere, int l);
Real mie_series_term(Real hg, Real g, int l, Real g_l_minus_2);

// lut_coordinates.glsl
Real texture_coord_from_unit_range(Real x, Real texture_size);
Real unit_range_from_texture_coord(Real u, Real texture_size);
Real sky_irradiance_u_from_mu_s(Real mu_s);
Real mu_s_from_sky_irradiance_u(Real x);

// transmittance.glsl
Real path_to_top_sample(const Atmosphere& atmosphere, Real r, Real mu, Real length_to_top, int i,
                        int steps, Real& weight);
Real3 optical_depth_to_top(const Atmosphere& atmosphere, Real r, Real mu, int steps);
Real3 transmittance_to_top(const Atmosphere& atmosphere, Real r, Real mu, int steps);
Real erfcx(Real x);
Real chapman_optical_depth_to_infinity(Real r_ref, Real scale_height, Real r, Real mu);
Real exponential_optical_depth_to_top(const Atmosphere& atmosphere, Real scale_height, Real r,
                                      Real mu);
Real2 transmittance_uv_from_r_mu(const Atmosphere& atmosphere, Real r, Real mu, Real2 size);
Real2 transmittance_r_mu_from_uv(const Atmosphere& atmosphere, Real2 uv, Real2 size);
void transmittance_lut_uv_from_r_mu(const Atmosphere& atmosphere, Real r, Real mu, Real& u,
                                    Real& v);
void transmittance_lut_r_mu_from_uv(const Atmosphere& atmosphere, Real u, Real v, Real& r,
                                    Real& mu);

// sun.glsl
Real3 sun_disk_radiance(const Atmosphere& atmosphere, Real cos_angle);

// occluded_sun.glsl
Real circle_overlap_area(Real a, Real b, Real d);
Real3 sun_flux_within(Real x);
Real3 occluded_sun_fraction(Real3 sun_dir, Real sun_radius, Real3 moon_centre, Real moon_radius);
bool moon_hides_sun(Real3 o, Real3 d, Real3 moon_centre, Real moon_radius);

// The model as the shared functions see it.
Atmosphere to_shared(const AtmosphereModel& model);

}  // namespace planet::shared
