// The density of each component and the extinction it makes (the shared
// math: see definitions.glsl).
Real layer_density(IN(DensityLayer) layer, Real altitude) {
  Real density = layer.exp_term * exp(layer.exp_scale * altitude) +
                 layer.linear_term * altitude + layer.constant_term;
  return clamp(density, Real(0.0), Real(1.0));
}

// Below the bottom (a ray grazing the ground, rounded a hair under it) the
// air is that of the ground, not the first layer's extrapolation.
Real profile_density(IN(DensityProfile) profile, Real altitude) {
  Real h = max(altitude, Real(0.0));
  return h < profile.layers[0].width ? layer_density(profile.layers[0], h)
                                     : layer_density(profile.layers[1], h);
}

// Extinction (1/m) per channel at an altitude above the bottom radius.
Real3 extinction_at(IN(Atmosphere) atmosphere, Real altitude) {
  return atmosphere.rayleigh_scattering * profile_density(atmosphere.rayleigh_density, altitude) +
         atmosphere.mie_extinction * profile_density(atmosphere.mie_density, altitude) +
         atmosphere.absorption_extinction *
             profile_density(atmosphere.absorption_density, altitude);
}
