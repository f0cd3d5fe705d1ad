// The clouds' phase function (the shared cloud math, see
// cloud_definitions.glsl), per steradian, integrating to 1; nu is the cosine
// of the scattering angle. Needs kPi and henyey_greenstein_phase from
// atmosphere/shaders/phase.glsl.

// Draine 2003, eq. 4: Henyey-Greenstein times (1 + alpha nu^2), normalised;
// alpha = 0 is Henyey-Greenstein, alpha = 1, g = 0 Rayleigh's shape.
Real draine_phase(Real g, Real alpha, Real nu) {
  Real denom = Real(1.0) + g * g - Real(2.0) * g * nu;
  return (Real(1.0) - g * g) * (Real(1.0) + alpha * nu * nu) /
         (Real(4.0) * kPi * (Real(1.0) + alpha * (Real(1.0) + Real(2.0) * g * g) / Real(3.0)) *
          denom * sqrt(denom));
}

// Jendersie and d'Eon 2023, "An Approximate Mie Scattering Function for Fog
// and Cloud Rendering": the blend (1 - w_D) HG(g_HG) + w_D Draine(g_D,
// alpha) fitted to Lorenz-Mie for water droplets of diameter d; their fits
// for 1.5 <= d < 5 um and 5 <= d <= 50 um (d is clamped to [1.5, 50]).
// Returns (g_HG, g_D, alpha, w_D).
Real3 cloud_mie_fit_lobes(Real d, OUT(Real) w_d) {
  d = clamp(d, Real(1.5), Real(50.0));
  if (d >= Real(5.0)) {
    w_d = exp(Real(-0.599085) / (d - Real(0.641583)) - Real(0.665888));
    return Real3(exp(Real(-0.0990567) / (d - Real(1.67154))),
                 exp(Real(-2.20679) / (d + Real(3.91029)) - Real(0.428934)),
                 exp(Real(3.62489) - Real(8.29288) / (d + Real(5.52825))));
  }
  Real ln_d = log(d);
  w_d = Real(0.026914) * (ln_d - cos(Real(5.68947) * (log(ln_d) - Real(0.0292149)))) +
        Real(0.376475);
  return Real3(Real(0.0604931) * log(ln_d) + Real(0.940256),
               Real(0.500411) - Real(0.081287) / (Real(-2.0) * ln_d + tan(ln_d) + Real(1.27551)),
               Real(7.30354) * ln_d + Real(6.31675));
}

Real cloud_phase(Real droplet_diameter_um, Real nu) {
  Real w_d;
  Real3 lobes = cloud_mie_fit_lobes(droplet_diameter_um, w_d);
  return (Real(1.0) - w_d) * henyey_greenstein_phase(lobes.x, nu) +
         w_d * draine_phase(lobes.y, lobes.z, nu);
}
