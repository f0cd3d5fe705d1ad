// Lambertian ground at the end of a ray, lit by the sun through the
// atmosphere by the including technique's transmittance_lookup (see
// sunlight.glsl); the sky's own light on the ground is left out, as in the
// reference implementation of Hillaire 2020.
Real3 ground_radiance(IN(Atmosphere) atmosphere, IN(Real3) p, IN(Real3) sun_dir) {
  Real r = length(p);
  Real mu_s = clamp_cosine(dot(p, sun_dir) / r);
  Real3 sun = mu_s > Real(0.0) ? transmittance_lookup(atmosphere, atmosphere.bottom_radius, mu_s)
                               : Real3(0.0);
  return atmosphere.ground_albedo / kPi * sun * max(mu_s, Real(0.0));
}
