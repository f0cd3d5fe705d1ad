// The radiance of the order before, arriving at r along zenith cosine mu
// with the sun at mu_s and at cosine nu from the view: from the single
// scattering's Rayleigh and Mie tables with their phase functions (order 1,
// FIRST_ORDER), or from the last order's own table.
#ifdef FIRST_ORDER
layout(binding = 1) uniform sampler3D u_order_rayleigh;
layout(binding = 2) uniform sampler3D u_order_mie;
#else
layout(binding = 1) uniform sampler3D u_order_multiple;
#endif

vec3 order_radiance(Atmosphere atmosphere, float r, float mu, float mu_s, float nu, bool ground) {
#ifdef FIRST_ORDER
  vec3 rayleigh = bruneton_scattering_lookup(atmosphere, u_order_rayleigh, r, mu, mu_s, nu, ground).rgb;
  vec3 mie = bruneton_scattering_lookup(atmosphere, u_order_mie, r, mu, mu_s, nu, ground).rgb;
  return rayleigh * rayleigh_phase(nu) + mie * mie_phase(atmosphere, nu);
#else
  return bruneton_scattering_lookup(atmosphere, u_order_multiple, r, mu, mu_s, nu, ground).rgb;
#endif
}
