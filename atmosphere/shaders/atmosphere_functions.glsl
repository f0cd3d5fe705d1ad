// The atmosphere's shared math, written once in the common subset of GLSL
// and C++-with-GLM: shaders #include it with Real = float, and the C++
// side (atmosphere/shared_math.h) includes it with Real = double, so the
// ground truth and the tests run the very same formulas as the GPU.
// The including side defines Real, Real2, Real3, IN(T), OUT(T) and the struct
// Atmosphere below is shared as written.
//
// Conventions (Bruneton 2017): r is the distance from the planet's centre,
// mu the cosine of the view zenith angle, mu_s that of the sun zenith angle,
// nu the cosine of the angle between view and sun. Lengths in metres.

struct DensityLayer {
  Real width;
  Real exp_term;
  Real exp_scale;
  Real linear_term;
  Real constant_term;
};

struct DensityProfile {
  DensityLayer layers[2];
};

struct Atmosphere {
  Real bottom_radius;
  Real top_radius;
  Real3 solar_irradiance;
  Real sun_angular_radius;
  Real3 rayleigh_scattering;
  DensityProfile rayleigh_density;
  Real3 mie_scattering;
  Real3 mie_extinction;
  Real mie_g;
  DensityProfile mie_density;
  Real3 absorption_extinction;
  DensityProfile absorption_density;
  Real3 ground_albedo;
};

const Real kPi = 3.14159265358979323846;

Real clamp_cosine(Real mu) { return clamp(mu, Real(-1.0), Real(1.0)); }

Real safe_sqrt(Real a) { return sqrt(max(a, Real(0.0))); }

// --- Ray and sphere --------------------------------------------------------
// Distances along the ray o + t d (d unit) to a sphere of radius R about the
// origin. The discriminant is R^2 - p^2 with p the distance of closest
// approach, formed as (R - p)(R + p) from the vector o - (o.d) d, so that it
// keeps its precision for grazing rays and for origins far from the planet,
// where the textbook b^2 - c cancels catastrophically (b^2 and c are both
// ~|o|^2, 1e18 m^2 at 1e9 m). Returns false when the line misses.
bool ray_sphere(IN(Real3) o, IN(Real3) d, Real R, OUT(Real) t_near, OUT(Real) t_far) {
  Real b = dot(o, d);
  Real3 closest = o - b * d;
  Real p = length(closest);
  Real disc = (R - p) * (R + p);
  if (disc < Real(0.0)) {
    t_near = Real(0.0);
    t_far = Real(0.0);
    return false;
  }
  Real q = sqrt(disc);
  t_near = -b - q;
  t_far = -b + q;
  return true;
}

// Bruneton 2017, DistanceToTopAtmosphereBoundary: from radius r inside the
// shell, along a ray of zenith cosine mu.
Real distance_to_top_boundary(IN(Atmosphere) atmosphere, Real r, Real mu) {
  Real disc = r * r * (mu * mu - Real(1.0)) + atmosphere.top_radius * atmosphere.top_radius;
  return max(-r * mu + safe_sqrt(disc), Real(0.0));
}

Real distance_to_bottom_boundary(IN(Atmosphere) atmosphere, Real r, Real mu) {
  Real disc =
      r * r * (mu * mu - Real(1.0)) + atmosphere.bottom_radius * atmosphere.bottom_radius;
  return max(-r * mu - safe_sqrt(disc), Real(0.0));
}

bool ray_intersects_ground(IN(Atmosphere) atmosphere, Real r, Real mu) {
  return mu < Real(0.0) &&
         r * r * (mu * mu - Real(1.0)) + atmosphere.bottom_radius * atmosphere.bottom_radius >=
             Real(0.0);
}

// --- Density ---------------------------------------------------------------
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

// --- Phase functions (per steradian, integrating to 1 over the sphere) -----
Real isotropic_phase() { return Real(1.0) / (Real(4.0) * kPi); }

// Rayleigh 1871: 3/(16 pi) (1 + nu^2).
Real rayleigh_phase(Real nu) { return Real(3.0) / (Real(16.0) * kPi) * (Real(1.0) + nu * nu); }

// Henyey and Greenstein 1941.
Real henyey_greenstein_phase(Real g, Real nu) {
  Real denom = Real(1.0) + g * g - Real(2.0) * g * nu;
  return (Real(1.0) - g * g) / (Real(4.0) * kPi * denom * sqrt(denom));
}

// Cornette and Shanks 1992: Henyey-Greenstein with a Rayleigh-like (1 + nu^2)
// factor, renormalised; the Mie phase of Bruneton 2017 and Hillaire 2020.
Real cornette_shanks_phase(Real g, Real nu) {
  Real k = Real(3.0) / (Real(8.0) * kPi) * (Real(1.0) - g * g) / (Real(2.0) + g * g);
  Real denom = Real(1.0) + g * g - Real(2.0) * g * nu;
  return k * (Real(1.0) + nu * nu) / (denom * sqrt(denom));
}

// --- Optical depth ----------------------------------------------------------
// Numerical optical depth from radius r along zenith cosine mu to the top
// boundary, per channel: the trapezoid rule over `steps` intervals of u,
// with the sample at distance t = L u^2 (L the distance to the top). The
// samples crowd near the start, where the air is densest on any ray that
// does not dip below its start's altitude by much; on Earth, 40 uniform
// steps put 0.018 too much optical depth on a ray 2 deg above the horizon
// (transmittance 1-2 % low at sunset), 40 of these 0.0044 at worst.
//
// Sample i (1 to steps) of that rule on the path of length L: the altitude
// there, and its weight, which the sum times L / steps turns into dt.
Real path_to_top_sample(IN(Atmosphere) atmosphere, Real r, Real mu, Real length_to_top, int i,
                        int steps, OUT(Real) weight) {
  Real u = Real(i) / Real(steps);
  Real t = length_to_top * u * u;
  // dt = 2 L u du; the sample at u = 0 has weight 0.
  weight = (i == steps ? Real(0.5) : Real(1.0)) * Real(2.0) * u;
  // Law of cosines: radius at distance t along the ray.
  return sqrt(t * t + Real(2.0) * r * mu * t + r * r) - atmosphere.bottom_radius;
}

Real3 optical_depth_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  Real length_to_top = distance_to_top_boundary(atmosphere, r, mu);
  Real3 sum = Real3(0.0);
  for (int i = 1; i <= steps; ++i) {
    Real weight;
    Real altitude = path_to_top_sample(atmosphere, r, mu, length_to_top, i, steps, weight);
    sum += weight * extinction_at(atmosphere, altitude);
  }
  return sum * (length_to_top / Real(steps));
}

Real3 transmittance_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  return exp(-optical_depth_to_top(atmosphere, r, mu, steps));
}

// --- Ray and shell -----------------------------------------------------------
// The first stretch of the ray o + t d (t >= 0) inside the shell
// r_inner <= |x| <= r_outer: [t_enter, t_exit]. The stretch ends where the
// ray meets the inner sphere (the ground) or leaves the outer one; an origin
// inside the inner sphere enters the shell where it leaves that sphere.
// Returns false when the ray never enters the shell.
bool ray_shell(IN(Real3) o, IN(Real3) d, Real r_inner, Real r_outer, OUT(Real) t_enter,
               OUT(Real) t_exit) {
  Real outer_near, outer_far;
  t_enter = Real(0.0);
  t_exit = Real(0.0);
  if (!ray_sphere(o, d, r_outer, outer_near, outer_far) || outer_far <= Real(0.0)) return false;
  t_enter = max(outer_near, Real(0.0));
  t_exit = outer_far;
  Real inner_near, inner_far;
  if (ray_sphere(o, d, r_inner, inner_near, inner_far)) {
    if (inner_near > t_enter) {
      t_exit = min(t_exit, inner_near);
    } else if (inner_far > t_enter) {
      t_enter = inner_far;  // starts inside the inner sphere
    }
  }
  return t_exit > t_enter;
}

// --- Analytic optical depth of one exponential layer ---------------------------
// e^(x^2) erfc(x) for x >= 0: Numerical Recipes' Chebyshev fit of erfc
// (Press et al. 2007, section 6.2.2, fractional error below 1.2e-7), which
// is already the scaled form t exp(P(t)), so it never overflows.
Real erfcx(Real x) {
  Real t = Real(1.0) / (Real(1.0) + Real(0.5) * x);
  Real p = Real(-1.26551223) +
           t * (Real(1.00002368) +
           t * (Real(0.37409196) +
           t * (Real(0.09678418) +
           t * (Real(-0.18628806) +
           t * (Real(0.27886807) +
           t * (Real(-1.13520398) +
           t * (Real(1.48851587) + t * (Real(-0.82215223) + t * Real(0.17087277)))))))));
  return t * exp(p);
}

// The integral of exp(-(|x(t)| - r_ref) / H) along the ray from radius r
// with zenith cosine mu >= 0 to infinity (Chapman 1931's grazing-incidence
// integral, divided out as H exp(-(r - r_ref) / H) Ch). With z = H u the
// height gained, the exact integral is
//   H e^(-(r - r_ref)/H) int_0^inf e^-u (x + u) / sqrt(x^2 mu^2 + 2 x u + u^2) du,
// x = r / H. Expanding 1 / sqrt(a + u^2), a = 2 x (c + u), c = x mu^2 / 2, to
// first order in 1/x leaves three incomplete gamma integrals:
//   sqrt(x/2) G(1/2) + (G(3/2) - c G(1/2)) / sqrt(2x)
//   - (G(3/2) - 2 c G(1/2) + c^2 G(-1/2)) / (4 sqrt(2x)),
// with G(s) = e^c Gamma(s, c): G(1/2) = sqrt(pi) erfcx(sqrt c),
// G(3/2) = G(1/2) / 2 + sqrt c, c^2 G(-1/2) = 2 c (sqrt c - c G(1/2)).
// The leading term alone is the classic erfc form of the Chapman function,
// off by O(1/x) (1e-3 for Earth's Rayleigh layer); the neglected terms are
// O(1/x^2), below 1e-5 for Earth.
Real chapman_optical_depth_to_infinity(Real r_ref, Real scale_height, Real r, Real mu) {
  Real x = r / scale_height;
  Real c = Real(0.5) * x * mu * mu;
  Real y = sqrt(c);
  Real g_half = sqrt(kPi) * erfcx(y);
  Real g_three_halves = Real(0.5) * g_half + y;
  Real c2_g_minus_half = Real(2.0) * c * (y - c * g_half);
  Real inv_sqrt_2x = Real(1.0) / sqrt(Real(2.0) * x);
  Real sum = sqrt(Real(0.5) * x) * g_half + (g_three_halves - c * g_half) * inv_sqrt_2x -
             Real(0.25) * inv_sqrt_2x * (g_three_halves - Real(2.0) * c * g_half + c2_g_minus_half);
  return scale_height * exp(-(r - r_ref) / scale_height) * sum;
}

// The integral of density exp(-altitude / H) from radius r along zenith
// cosine mu to the top boundary, for a ray that does not meet the ground
// (multiply by a coefficient for optical depth). The part beyond the top is
// subtracted; a downward ray is split at its perigee r_p = r sqrt(1 - mu^2),
// where it is horizontal, into two upward halves.
Real exponential_optical_depth_to_top(IN(Atmosphere) atmosphere, Real scale_height, Real r,
                                      Real mu) {
  Real R = atmosphere.bottom_radius;
  Real top = atmosphere.top_radius;
  // At the exit point r_top mu_top = r mu + d (d the distance travelled).
  Real d = distance_to_top_boundary(atmosphere, r, mu);
  Real mu_top = clamp_cosine((r * mu + d) / top);
  Real beyond = chapman_optical_depth_to_infinity(R, scale_height, top, mu_top);
  if (mu >= Real(0.0)) {
    return chapman_optical_depth_to_infinity(R, scale_height, r, mu) - beyond;
  }
  Real r_p = r * sqrt(max(Real(1.0) - mu * mu, Real(0.0)));
  return Real(2.0) * chapman_optical_depth_to_infinity(R, scale_height, r_p, Real(0.0)) -
         chapman_optical_depth_to_infinity(R, scale_height, r, -mu) - beyond;
}

// --- Transmittance LUT parameterisation (Bruneton 2017, section 4) -----------
// x_r = rho / H with rho the distance to the horizon and H its value at the
// top; x_mu spreads the distance to the top between its extremes d_min and
// d_max. Texel centres sit at 0.5 / n and 1 - 0.5 / n so that the extremes
// are sampled exactly.
Real texture_coord_from_unit_range(Real x, Real texture_size) {
  return Real(0.5) / texture_size + x * (Real(1.0) - Real(1.0) / texture_size);
}

Real unit_range_from_texture_coord(Real u, Real texture_size) {
  return (u - Real(0.5) / texture_size) / (Real(1.0) - Real(1.0) / texture_size);
}

Real2 transmittance_uv_from_r_mu(IN(Atmosphere) atmosphere, Real r, Real mu, Real2 size) {
  Real H = sqrt(atmosphere.top_radius * atmosphere.top_radius -
                atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real rho = safe_sqrt(r * r - atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real d = distance_to_top_boundary(atmosphere, r, mu);
  Real d_min = atmosphere.top_radius - r;
  Real d_max = rho + H;
  Real x_mu = (d - d_min) / (d_max - d_min);
  Real x_r = rho / H;
  return Real2(texture_coord_from_unit_range(x_mu, size.x),
               texture_coord_from_unit_range(x_r, size.y));
}

// The inverse: (r, mu) at texture coordinates uv. Returns (r, mu).
Real2 transmittance_r_mu_from_uv(IN(Atmosphere) atmosphere, Real2 uv, Real2 size) {
  Real x_mu = unit_range_from_texture_coord(uv.x, size.x);
  Real x_r = unit_range_from_texture_coord(uv.y, size.y);
  Real H = sqrt(atmosphere.top_radius * atmosphere.top_radius -
                atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real rho = H * x_r;
  Real r = sqrt(rho * rho + atmosphere.bottom_radius * atmosphere.bottom_radius);
  Real d_min = atmosphere.top_radius - r;
  Real d_max = rho + H;
  Real d = d_min + x_mu * (d_max - d_min);
  // Law of cosines at the top: top^2 = r^2 + d^2 + 2 r d mu.
  Real mu = d == Real(0.0) ? Real(1.0) : (H * H - rho * rho - d * d) / (Real(2.0) * r * d);
  return Real2(r, clamp_cosine(mu));
}

// The sun's zenith cosine mu_s -> [0, 1] as (1 + sign(mu_s) sqrt(|mu_s|)) / 2,
// and back: packs samples around the terminator (mu_s = 0), where the light
// at a point changes fastest. Hillaire's multiple-scattering LUT and the
// ground's sky-irradiance table use it.
Real sky_irradiance_u_from_mu_s(Real mu_s) {
  Real m = clamp(mu_s, Real(-1.0), Real(1.0));
  return Real(0.5) + Real(0.5) * sign(m) * sqrt(abs(m));
}

Real mu_s_from_sky_irradiance_u(Real x) {
  Real s = Real(2.0) * x - Real(1.0);
  return s * abs(s);
}
