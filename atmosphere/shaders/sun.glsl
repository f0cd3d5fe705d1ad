// The sun's disk (the shared math: see definitions.glsl). Limb darkening by the power law I(mu) = I(1) mu^alpha of Hestroffer and
// Magnan 1998, alpha = 0.397, 0.503, 0.652 at 680, 550, 440 nm, with mu the
// cosine on the solar surface (sqrt(1 - x^2), x the fraction of the disk's
// radius). Normalised so that the disk's irradiance is the body's solar
// irradiance: int mu^alpha over the disk = (solid angle) 2 / (alpha + 2).
const Real3 kLimbDarkening = Real3(0.397, 0.503, 0.652);

Real3 sun_disk_radiance(IN(Atmosphere) atmosphere, Real cos_angle) {
  Real cos_alpha = cos(atmosphere.sun_angular_radius);
  if (cos_angle <= cos_alpha) return Real3(0.0);
  Real solid_angle = Real(2.0) * kPi * (Real(1.0) - cos_alpha);
  Real angle = acos(clamp_cosine(cos_angle));
  Real x = min(angle / atmosphere.sun_angular_radius, Real(1.0));
  Real mu = safe_sqrt(Real(1.0) - x * x);
  Real3 alpha = kLimbDarkening;
  Real3 darkening = Real3(pow(mu, alpha.x), pow(mu, alpha.y), pow(mu, alpha.z));
  return atmosphere.solar_irradiance / solid_angle * (alpha + Real3(2.0)) * Real(0.5) * darkening;
}
