// The atmosphere's shared math, written once in the common subset of GLSL
// and C++-with-GLM: shaders #include it with Real = float, and the C++
// side (atmosphere/shared_math.h) includes it with Real = double, so the
// ground truth and the tests run the very same formulas as the GPU.
// The including side defines Real, Real3, IN(T), OUT(T) and the struct
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
// Numerical optical depth (trapezoid rule, `steps` intervals) from radius r
// along zenith cosine mu to the top boundary, per channel.
Real3 optical_depth_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  Real length_to_top = distance_to_top_boundary(atmosphere, r, mu);
  Real dt = length_to_top / Real(steps);
  Real3 sum = Real3(0.0);
  for (int i = 0; i <= steps; ++i) {
    Real t = Real(i) * dt;
    // Law of cosines: radius at distance t along the ray.
    Real r_t = sqrt(t * t + Real(2.0) * r * mu * t + r * r);
    Real weight = (i == 0 || i == steps) ? Real(0.5) : Real(1.0);
    sum += weight * extinction_at(atmosphere, r_t - atmosphere.bottom_radius);
  }
  return sum * dt;
}

Real3 transmittance_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  return exp(-optical_depth_to_top(atmosphere, r, mu, steps));
}
