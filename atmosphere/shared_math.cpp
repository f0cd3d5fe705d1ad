#include "atmosphere/shared_math.h"

namespace planet::shared {

namespace {

DensityProfile to_shared(const planet::DensityProfile& p) {
  DensityProfile out{};
  for (int i = 0; i < 2; ++i) {
    const auto& l = p.layers[size_t(i)];
    out.layers[i] = {l.width, l.exp_term, l.exp_scale, l.linear_term, l.constant_term};
  }
  return out;
}

}  // namespace

Atmosphere to_shared(const AtmosphereModel& m) {
  Atmosphere a{};
  a.bottom_radius = m.bottom_radius;
  a.top_radius = m.top_radius;
  a.solar_irradiance = m.solar_irradiance;
  a.sun_angular_radius = m.sun_angular_radius;
  a.rayleigh_scattering = m.rayleigh.scattering;
  a.rayleigh_density = to_shared(m.rayleigh.density);
  a.mie_scattering = m.mie.scattering;
  a.mie_extinction = m.mie.extinction();
  a.mie_g = m.mie_g;
  a.mie_density = to_shared(m.mie.density);
  a.absorption_extinction = m.absorber.extinction();
  a.absorption_density = to_shared(m.absorber.density);
  a.ground_albedo = Real3(m.ground_albedo);
  return a;
}

}  // namespace planet::shared
