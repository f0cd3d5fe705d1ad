// Rays, spheres and the atmosphere's shell (the shared math: see
// definitions.glsl).
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
