// Hillaire 2020, "A Scalable and Production Ready Sky and Atmosphere
// Rendering Technique": the scattering integrals along a ray, in the common
// subset of GLSL and C++-with-GLM (see definitions.glsl). The shaders of
// atmosphere/gpu/hillaire (hillaire_common.glsl) and its CPU side
// (atmosphere/math/hillaire_math.cpp) compile this same file, after the
// shared math, hillaire_definitions.glsl, sunlight.glsl, ground.glsl and
// hillaire_luts.glsl; hillaire_orders.glsl, the multiple-scattering LUT's
// texels, comes after it.
//
// The including side declares, before including this file and those two
// (and defines anywhere):
//   Real3 transmittance_lookup(IN(Atmosphere), Real r, Real mu)
//       transmittance from radius r to the top along zenith cosine mu
//   Real3 multiple_scattering_lookup(Real u, Real v, int part)
//       the multiple-scattering LUT's part (FieldMoments) at its texture
//       coordinates (multiple_scattering_lut_uv_from_r_mu_s), per unit solar
//       irradiance: part kFieldMean is Psi_ms (Hillaire 2020, eq. 10)
//   Real3 scattering_order_lookup(Real u, Real v, int part)
//       the previous order's part likewise (part kFieldMean: J_n)
//   Real3 ground_order_lookup(IN(Atmosphere), Real mu_s)
//       E_n, that order's irradiance on the ground
//   Real mie_column_lookup(IN(Atmosphere), Real r, Real mu)
//       the Mie density integrated from radius r to the top along zenith
//       cosine mu, in metres (mie_column_to_top)
//   Real forward_gain_lookup(IN(Atmosphere), Real nu, Real tau)
//       forward_gain_times_extinction (see "The sun's glow past the
//       table's degree"), or zero where a technique leaves the gain out
//   Real terrain_sun_visibility(IN(Real3) p)
//       1 where the terrain leaves the sun in view of the point p, 0 in
//       its shadow (terrain_shadow.glsl; 1 on the CPU and in the LUTs)
//   Real3 eclipse_sun_share(IN(Real3) p, IN(Real3) sun_dir)
//       the visible share of the sun at p with the Moon before it
//       (occluded_sun.glsl; 1 but in an eclipse, and on the CPU)
// and, with TERRAIN_SHADOW_LOSS defined, a Real3 terrain_shadow_loss that
// the sun's light the terrain took away along the ray is added to.
// On the GPU these sample the LUTs; on the CPU they integrate directly or
// read tables.

// --- Scattering along a ray ---------------------------------------------------
// (1 - exp(-x)) / x, stable at x -> 0 where float loses 1 - exp(-x).
Real one_minus_exp_over_x(Real x) {
  return x < Real(1e-4) ? Real(1.0) - Real(0.5) * x : (Real(1.0) - exp(-x)) / x;
}

Real3 one_minus_exp_over_x3(IN(Real3) x) {
  return Real3(one_minus_exp_over_x(x.x), one_minus_exp_over_x(x.y), one_minus_exp_over_x(x.z));
}

// B_lm(d) for part k = (l, m), d = (x, y, z) in the local frame:
//   sqrt((2l + 1)(l - m)! / (l + m)!) (times sqrt 2 for m > 0) Q_lm(z) R_m,
// with Q_lm the associated Legendre function over sin^m(theta) (Q_mm =
// (2m - 1)!!, Q_(m+1)m = (2m + 1) z Q_mm, and Bonnet's recursion in l) and
// R_m = Re((x + i y)^m) = sin^m(theta) cos(m phi). Written out to degree 4
// so that the compiler folds it into each call's few products.
Real field_basis(int part, Real x, Real y, Real z) {
  Real zz = z * z;
  Real r2 = x * x - y * y;
  Real r3 = x * r2 - Real(2.0) * x * y * y;
  Real r4 = r2 * r2 - Real(4.0) * x * x * y * y;
  if (part == 0) return Real(1.0);
  if (part == 1) return sqrt(Real(3.0)) * z;
  if (part == 2) return sqrt(Real(3.0)) * x;
  if (part == 3) return sqrt(Real(5.0)) * Real(0.5) * (Real(3.0) * zz - Real(1.0));
  if (part == 4) return sqrt(Real(5.0) / Real(3.0)) * Real(3.0) * z * x;
  if (part == 5) return sqrt(Real(5.0) / Real(12.0)) * Real(3.0) * r2;
  if (part == 6) return sqrt(Real(7.0)) * Real(0.5) * (Real(5.0) * zz - Real(3.0)) * z;
  if (part == 7) return sqrt(Real(7.0) / Real(6.0)) * Real(0.5) * (Real(15.0) * zz - Real(3.0)) * x;
  if (part == 8) return sqrt(Real(7.0) / Real(60.0)) * Real(15.0) * z * r2;
  if (part == 9) return sqrt(Real(7.0) / Real(360.0)) * Real(15.0) * r3;
  if (part == 10) return Real(3.0) / Real(8.0) * ((Real(35.0) * zz - Real(30.0)) * zz + Real(3.0));
  if (part == 11) {
    return sqrt(Real(9.0) / Real(10.0)) * Real(0.5) * (Real(35.0) * zz - Real(15.0)) * z * x;
  }
  if (part == 12) return sqrt(Real(1.0) / Real(20.0)) * Real(0.5) * (Real(105.0) * zz - Real(15.0)) * r2;
  if (part == 13) return sqrt(Real(1.0) / Real(280.0)) * Real(105.0) * z * r3;
  return sqrt(Real(1.0) / Real(2240.0)) * Real(105.0) * r4;
}

Real3 field_part(IN(FieldMoments) f, int part) { return f.part[part]; }

Real3 field_lookup(bool previous_order, Real u, Real v, int part) {
  return previous_order ? scattering_order_lookup(u, v, part)
                        : multiple_scattering_lookup(u, v, part);
}

// --- The sun's glow past the table's degree ------------------------------------
// The table carries each order's light by its terms up to degree
// kFieldDegree, and scattered_field scatters no more. Mie's forward peak
// lives in the terms past it, and so does the light it makes: round the
// sun, every point sees a glow of sunlight that the dust along the sun's
// path has scattered forward, once or many times (thick dust: the Mars
// sky). The glow's lower terms come back through the table's orders; the
// higher ones were lost, which took light from beside the sun and spread
// it over the sky: with the table to degree 2, Mars noon's sky toward the
// horizon came out 13-33 % too bright.
//
// Taken as spreading in angle alone, not sideways off the path (the air
// changes slowly across the few degrees of Mie's peak), each Mie
// scattering multiplies the term l of the beam's angular distribution by
// g_l (Funk-Hecke). Over Mie scattering optical depth tau from the top of
// the atmosphere along the sun's path, a Poisson number of them leaves term
// l of the sunlight arriving at a point at exp(g_l tau) times what
// extinction left of the beam: the beam itself and its glow. Scattered
// there toward the camera, the glow's terms past L = kFieldDegree add to
// the sun's phase
//   forward_gain(nu, tau) = sum over l > L of (2l + 1) / (4 pi) g_l (exp(g_l tau) - 1) P_l(nu)
// per unit of Mie scattering. It is zero at tau = 0 and integrates to zero
// over the sphere: it moves light toward the sun and makes none. It depends
// on g and (nu, tau) alone: the forward-gain LUT holds it over (nu, tau).
// Against the path tracer's second order at Mars noon (with L = 2), its
// first term in tau made up 63-94 % of what the table missed toward the
// horizon and 84-132 % beside the sun.
//
// The same chain of forward scatterings as a source inside the orders
// (each order's terms past L, from this series) made Mars sunset worse
// (24.8 % red against 17.4 %): sparse gather directions see its broad
// negative part and miss its peak.
//
// exp(-tau) forward_gain, bounded (the beam has lost at least exp(-tau)
// of itself), summed over kForwardGainTerms terms.
Real forward_gain_times_extinction(Real g, Real hg, Real nu, Real tau) {
  Real legendre_before = nu;  // P_1
  Real legendre = Real(1.5) * nu * nu - Real(0.5);  // P_2
  Real sum = Real(0.0);
  Real g_l_minus_2 = Real(1.0);
  for (int l = 3; l <= kForwardGainTerms; ++l) {
    // Bonnet's recursion: l P_l = (2l - 1) nu P_(l-1) - (l - 1) P_(l-2).
    Real next = (Real(2 * l - 1) * nu * legendre - Real(l - 1) * legendre_before) / Real(l);
    legendre_before = legendre;
    legendre = next;
    g_l_minus_2 *= g;
    if (l <= kFieldDegree) continue;
    Real g_l = mie_series_term(hg, g, l, g_l_minus_2);
    sum += Real(2 * l + 1) / (Real(4.0) * kPi) * g_l * (exp((g_l - Real(1.0)) * tau) - exp(-tau)) *
           legendre;
  }
  return sum;
}

// The Mie density profile integrated from radius r along zenith cosine mu
// to the top, sampled as optical_depth_to_top samples its extinction.
Real mie_column_to_top(IN(Atmosphere) atmosphere, Real r, Real mu, int steps) {
  Real length_to_top = distance_to_top_boundary(atmosphere, r, mu);
  Real sum = Real(0.0);
  for (int i = 1; i <= steps; ++i) {
    Real weight;
    Real altitude = path_to_top_sample(atmosphere, r, mu, length_to_top, i, steps, weight);
    sum += weight * profile_density(atmosphere.mie_density, altitude);
  }
  return sum * (length_to_top / Real(steps));
}


// The gain in Mie scattering per channel for sunlight that crossed Mie
// scattering optical depth tau, seen at cosine nu to the sun; held where
// exp(tau) would overflow float, where the sun's light is long gone.
// GREY_MIE, where the model's Mie scattering is the same in every channel
// (so is tau), reads the table once for all three.
Real3 forward_gain(IN(Atmosphere) atmosphere, Real nu, IN(Real3) tau) {
  Real3 t = min(tau, Real3(80.0));
#ifdef GREY_MIE
  return exp(t) * forward_gain_lookup(atmosphere, nu, t.x);
#else
  return exp(t) * Real3(forward_gain_lookup(atmosphere, nu, t.x),
                        forward_gain_lookup(atmosphere, nu, t.y),
                        forward_gain_lookup(atmosphere, nu, t.z));
#endif
}

// The field's parts at (u, v) of its table (multiple_scattering_lut_uv_from_r_mu_s),
// the order before's or the multiple-scattering LUT's. Written out part by
// part: as a loop over the parts, llvmpipe ran the scattering-orders pass
// 2.2 times slower.
FieldMoments field_at(bool previous_order, Real u, Real v) {
  FieldMoments f;
  f.part[0] = field_lookup(previous_order, u, v, 0);
  f.part[1] = field_lookup(previous_order, u, v, 1);
  f.part[2] = field_lookup(previous_order, u, v, 2);
  f.part[3] = field_lookup(previous_order, u, v, 3);
  f.part[4] = field_lookup(previous_order, u, v, 4);
  f.part[5] = field_lookup(previous_order, u, v, 5);
  f.part[6] = field_lookup(previous_order, u, v, 6);
  f.part[7] = field_lookup(previous_order, u, v, 7);
  f.part[8] = field_lookup(previous_order, u, v, 8);
  f.part[9] = field_lookup(previous_order, u, v, 9);
  f.part[10] = field_lookup(previous_order, u, v, 10);
  f.part[11] = field_lookup(previous_order, u, v, 11);
  f.part[12] = field_lookup(previous_order, u, v, 12);
  f.part[13] = field_lookup(previous_order, u, v, 13);
  f.part[14] = field_lookup(previous_order, u, v, 14);
  return f;
}

// The field's parts for the point p, from the order before's table or the
// multiple-scattering LUT.
FieldMoments field_at_point(IN(Atmosphere) atmosphere, bool previous_order, IN(Real3) p,
                            IN(Real3) sun_dir) {
  Real r = length(p);
  Real u, v;
  multiple_scattering_lut_uv_from_r_mu_s(atmosphere, r, clamp_cosine(dot(p, sun_dir) / r), u, v);
  return field_at(previous_order, u, v);
}

// The light of a field (the multiple-scattering LUT's, or the previous
// order's) arriving at p, scattered toward a camera that looks along d.
// By Funk-Hecke, a phase function with Legendre coefficients g_l (p = sum
// of (2l + 1) / (4 pi) g_l P_l) scatters the field's degree l times g_l:
// sigma times the sum over (l, m) of g_l f_lm B_lm(d). Rayleigh has g_0 =
// 1, g_2 = 1/10 and no others, so the table scatters it exactly; Mie's g_l
// past kFieldDegree are left to the glow's gain (forward_gain). Hillaire
// keeps the mean alone, which spreads the forward glow of thick dust over
// the whole sky and misses the sky's brightening toward the horizon. Each
// phase's sum is held at zero where the truncated series would go
// negative. `f` holds the field's parts where p lies (field_at), r is
// |p|; `rayleigh` and `mie` are the light scattered per unit of each
// scattering coefficient.
void field_radiance(IN(Atmosphere) atmosphere, IN(FieldMoments) f, Real r, IN(Real3) p,
                    IN(Real3) d, IN(Real3) sun_dir, OUT(Real3) rayleigh, OUT(Real3) mie) {
  Real3 up = p / r;
  Real3 horizontal = sun_dir - up * dot(up, sun_dir);
  Real h = length(horizontal);
  Real z = dot(d, up);
  Real x = h > Real(1e-6) ? dot(d, horizontal) / h : Real(0.0);
  // The field is even across the sun's vertical plane: the sign of y does
  // not matter.
  Real y = sqrt(max(Real(1.0) - z * z - x * x, Real(0.0)));
  Real3 degree_0 = f.part[0];
  Real3 degree_1 = field_basis(1, x, y, z) * f.part[1] + field_basis(2, x, y, z) * f.part[2];
  Real3 degree_2 = field_basis(3, x, y, z) * f.part[3] + field_basis(4, x, y, z) * f.part[4] +
                   field_basis(5, x, y, z) * f.part[5];
  Real3 degree_3 = field_basis(6, x, y, z) * f.part[6] + field_basis(7, x, y, z) * f.part[7] +
                   field_basis(8, x, y, z) * f.part[8] + field_basis(9, x, y, z) * f.part[9];
  Real3 degree_4 = field_basis(10, x, y, z) * f.part[10] + field_basis(11, x, y, z) * f.part[11] +
                   field_basis(12, x, y, z) * f.part[12] + field_basis(13, x, y, z) * f.part[13] +
                   field_basis(14, x, y, z) * f.part[14];
  rayleigh = max(degree_0 + Real(0.1) * degree_2, Real3(0.0));
  mie = max(degree_0 + mie_legendre(atmosphere, 1) * degree_1 +
                mie_legendre(atmosphere, 2) * degree_2 + mie_legendre(atmosphere, 3) * degree_3 +
                mie_legendre(atmosphere, 4) * degree_4,
            Real3(0.0));
}

// The same, scattered by sigma_r and sigma_m.
Real3 scattered_field_of(IN(Atmosphere) atmosphere, IN(FieldMoments) f, Real r,
                         IN(Real3) sigma_r, IN(Real3) sigma_m, IN(Real3) p, IN(Real3) d,
                         IN(Real3) sun_dir) {
  Real3 rayleigh, mie;
  field_radiance(atmosphere, f, r, p, d, sun_dir, rayleigh, mie);
  return sigma_r * rayleigh + sigma_m * mie;
}

// The same, the field read where p lies.
Real3 scattered_field(IN(Atmosphere) atmosphere, bool previous_order, Real r, Real mu_s,
                      IN(Real3) sigma_r, IN(Real3) sigma_m, IN(Real3) p, IN(Real3) d,
                      IN(Real3) sun_dir) {
  Real u, v;
  multiple_scattering_lut_uv_from_r_mu_s(atmosphere, r, mu_s, u, v);
  return scattered_field_of(atmosphere, field_at(previous_order, u, v), r, sigma_r, sigma_m, p, d,
                            sun_dir);
}

// One segment [t0, t1] of a ray o + t d, sampled at its middle. The source
// S is taken constant over the segment and the extinction integrated
// exactly: int_0^ds S exp(-sigma t) dt = S ds (1 - exp(-sigma ds)) / (sigma ds)
// (Hillaire 2015, "Physically Based and Unified Volumetric Rendering",
// energy-conserving integration). f_ms integrates the scattering alone
// (Hillaire 2020, eq. 8). Luminance is per unit solar irradiance.
// With `field_given`, the field's light (field_radiance, per unit of each
// scattering coefficient) is `field_rayleigh` and `field_mie`, which
// integrate_along read for more than one segment, and the segment reads no
// field of its own.
void accumulate_segment_in(IN(Atmosphere) atmosphere, IN(Real3) o, IN(Real3) d, Real t0, Real t1,
                           IN(Real3) sun_dir, Real phase_r, Real phase_m, int source_kind,
                           IN(Real3) field_rayleigh, IN(Real3) field_mie, bool field_given,
                           INOUT(Real3) luminance, INOUT(Real3) throughput,
                           INOUT(Real3) f_ms) {
  Real ds = t1 - t0;
  Real3 p = o + (Real(0.5) * (t0 + t1)) * d;
  Real r = length(p);
  Real altitude = r - atmosphere.bottom_radius;
  Real3 sigma_r =
      atmosphere.rayleigh_scattering * profile_density(atmosphere.rayleigh_density, altitude);
  Real3 sigma_m = atmosphere.mie_scattering * profile_density(atmosphere.mie_density, altitude);
  Real3 sigma_s = sigma_r + sigma_m;
  Real3 extinction = extinction_at(atmosphere, altitude);
  Real mu_s = clamp_cosine(dot(p, sun_dir) / r);
  Real3 source;
  if (source_kind == kSourceNextOrder) {
    source = field_given ? sigma_r * field_rayleigh + sigma_m * field_mie
                         : scattered_field(atmosphere, true, r, mu_s, sigma_r, sigma_m, p, d,
                                           sun_dir);
  } else {
    Real3 sun = sun_visibility(atmosphere, r, mu_s);
    if (source_kind == kSourceIsotropicSun) {
      source = sun * sigma_s * isotropic_phase();
    } else {
      Real3 direct = sun * (sigma_r * phase_r + sigma_m * phase_m);
      // The glow needs the sun: no lookups in the planet's shadow.
      if (source_kind == kSourceSky && sun.x + sun.y + sun.z > Real(0.0)) {
        Real3 tau_sun = atmosphere.mie_scattering * mie_column_lookup(atmosphere, r, mu_s);
        direct += sun * sigma_m * forward_gain(atmosphere, dot(d, sun_dir), tau_sun);
      }
      // Where the terrain hides the sun, its own light goes; the light the
      // air scattered more than once still comes from the whole sky.
      Real lit = terrain_sun_visibility(p);
      source = lit * direct;
#ifdef TERRAIN_SHADOW_LOSS
      terrain_shadow_loss += throughput * ds * one_minus_exp_over_x3(extinction * ds) *
                             (Real(1.0) - lit) * direct;
#endif
      if (source_kind == kSourceSky) {
        source += field_given ? sigma_r * field_rayleigh + sigma_m * field_mie
                              : scattered_field(atmosphere, false, r, mu_s, sigma_r, sigma_m, p,
                                                d, sun_dir);
        // The glow's gain and the field's moments are truncated series:
        // where the light is peaked more than they hold (Mie g 0.99) they
        // ring below zero, and no light is less than none (the stability
        // map found Mars at g 0.99, 0.1x density, 0.08 % of the sun below
        // zero).
        source = max(source, Real3(0.0));
      }
    }
    // In an eclipse, the Moon's share of the sun at p, for the sun's light
    // and the light scattered more than once alike: as if the shadow were
    // as wide as that light's reach (an approximation: docs/eclipses.md).
    // Last, and 1 exactly with no Moon, so that it changes no other sky.
    source *= eclipse_sun_share(p, sun_dir);
  }
  Real3 weight = throughput * ds * one_minus_exp_over_x3(extinction * ds);
  luminance += weight * source;
  f_ms += weight * sigma_s;
  throughput *= exp(-extinction * ds);
}

void accumulate_segment(IN(Atmosphere) atmosphere, IN(Real3) o, IN(Real3) d, Real t0, Real t1,
                        IN(Real3) sun_dir, Real phase_r, Real phase_m, int source_kind,
                        INOUT(Real3) luminance, INOUT(Real3) throughput, INOUT(Real3) f_ms) {
  accumulate_segment_in(atmosphere, o, d, t0, t1, sun_dir, phase_r, phase_m, source_kind,
                        Real3(0.0), Real3(0.0), false, luminance, throughput, f_ms);
}

// Segment i of a ray's steps, steps_before of them crowding toward
// t_closest from `before` ahead of it, the rest away from it over `after`.
void segment_bounds(int i, int steps_before, int steps_after, Real t_closest, Real before,
                    Real after, OUT(Real) t0, OUT(Real) t1) {
  if (i < steps_before) {
    Real a0 = Real(1.0) - Real(i) / Real(steps_before);
    Real a1 = Real(1.0) - Real(i + 1) / Real(steps_before);
    t0 = t_closest - before * a0 * a0;
    t1 = t_closest - before * a1 * a1;
  } else {
    Real b0 = Real(i - steps_before) / Real(steps_after);
    Real b1 = Real(i + 1 - steps_before) / Real(steps_after);
    t0 = t_closest + after * b0 * b0;
    t1 = t_closest + after * b1 * b1;
  }
}

// The field's light (field_radiance) at o + t d, read there.
void field_radiance_at(IN(Atmosphere) atmosphere, bool previous_order, IN(Real3) o, IN(Real3) d,
                       Real t, IN(Real3) sun_dir, OUT(Real3) rayleigh, OUT(Real3) mie) {
  Real3 p = o + t * d;
  field_radiance(atmosphere, field_at_point(atmosphere, previous_order, p, sun_dir), length(p), p,
                 d, sun_dir, rayleigh, mie);
}

// Scattered luminance (per unit solar irradiance), transmittance and f_ms
// along o + t d for t in [t_start, t_end], with `steps` segments. Segments
// crowd (square law) toward the point of the range closest to the planet's
// centre, where the air is densest: at the camera for a ray up from the
// ground, at the tangent point of a limb ray seen from space, at the ground
// for a ray down. `ends_at_ground` adds the lit ground behind the ray: by
// the sun, or for kSourceNextOrder by the previous order's sky light.
//
// `field_reads` says where the field (the multiple-scattering LUT's, or
// for kSourceNextOrder the order before's) is read; it changes slowly
// along a ray, and its 15 reads were half the cost of a step:
//   kFieldEachStep: at every segment's middle;
//   kFieldPerPair (an even number of steps): once for each pair of
//     segments, at the pair's middle, and scattered at each segment's own
//     point and direction (the sky pass's march);
//   kFieldInterpolated: at the even segments' middles, and for each odd
//     segment interpolated linearly along the ray between the reads either
//     side of it (an odd last segment, with none after it, reads its own).
//     The orders and the sky-view LUT take it: held constant over a pair,
//     the orders' 12 steps left the tenfold-dense Earth's blue 9.1 % off
//     the ground truth where every step's read gave 4.0. The sky pass's
//     march keeps the pairs: its steps vary from ray to ray, and there the
//     interpolation ran slower than the pairs.
void integrate_along(IN(Atmosphere) atmosphere, IN(Real3) o, IN(Real3) d, Real t_start,
                     Real t_end, IN(Real3) sun_dir, int steps, int source_kind, int field_reads,
                     bool ends_at_ground, OUT(Real3) luminance, OUT(Real3) transmittance,
                     OUT(Real3) f_ms) {
  luminance = Real3(0.0);
  transmittance = Real3(1.0);
  f_ms = Real3(0.0);
  Real nu = dot(d, sun_dir);
  Real phase_r = source_kind == kSourceSunMie ? Real(0.0) : rayleigh_phase(nu);
  Real phase_m = source_kind == kSourceSunMie
                     ? Real(1.0)
                     : (source_kind == kSourceSunRayleigh ? Real(0.0)
                                                          : mie_phase(atmosphere, nu));
  Real t_closest = clamp(-dot(o, d), t_start, t_end);
  Real before = t_closest - t_start;
  Real after = t_end - t_closest;
  Real total = before + after;
  int steps_before =
      total > Real(0.0) ? int(floor(Real(steps) * before / total + Real(0.5))) : 0;
  int steps_after = steps - steps_before;
  bool previous_order = source_kind == kSourceNextOrder;
  if (field_reads == kFieldInterpolated) {
    // The field's light at the last even segment's middle s_a (a_r, a_m)
    // and at the next one's s_b (b_r, b_m). No branch inside the loop:
    // llvmpipe runs both sides of one.
    Real t0, t1, t2, t3;
    segment_bounds(0, steps_before, steps_after, t_closest, before, after, t0, t1);
    Real s_a = Real(0.5) * (t0 + t1);
    Real3 a_r, a_m, b_r, b_m;
    field_radiance_at(atmosphere, previous_order, o, d, s_a, sun_dir, a_r, a_m);
    for (int i = 0; i + 2 < steps; i += 2) {
      accumulate_segment_in(atmosphere, o, d, t0, t1, sun_dir, phase_r, phase_m, source_kind, a_r,
                            a_m, true, luminance, transmittance, f_ms);
      segment_bounds(i + 1, steps_before, steps_after, t_closest, before, after, t2, t3);
      segment_bounds(i + 2, steps_before, steps_after, t_closest, before, after, t0, t1);
      Real s_b = Real(0.5) * (t0 + t1);
      field_radiance_at(atmosphere, previous_order, o, d, s_b, sun_dir, b_r, b_m);
      Real w = (Real(0.5) * (t2 + t3) - s_a) / max(s_b - s_a, Real(1e-6));
      accumulate_segment_in(atmosphere, o, d, t2, t3, sun_dir, phase_r, phase_m, source_kind,
                            mix(a_r, b_r, w), mix(a_m, b_m, w), true, luminance, transmittance,
                            f_ms);
      a_r = b_r;
      a_m = b_m;
      s_a = s_b;
    }
    // The last even segment, and after it, where the steps are even, the
    // last odd one, which has no read after it and reads its own.
    accumulate_segment_in(atmosphere, o, d, t0, t1, sun_dir, phase_r, phase_m, source_kind, a_r,
                          a_m, true, luminance, transmittance, f_ms);
    if ((steps & 1) == 0) {
      segment_bounds(steps - 1, steps_before, steps_after, t_closest, before, after, t2, t3);
      field_radiance_at(atmosphere, previous_order, o, d, Real(0.5) * (t2 + t3), sun_dir, b_r,
                        b_m);
      accumulate_segment_in(atmosphere, o, d, t2, t3, sun_dir, phase_r, phase_m, source_kind, b_r,
                            b_m, true, luminance, transmittance, f_ms);
    }
  } else {
    bool per_pair = field_reads == kFieldPerPair;
    for (int i = 0; i < steps; i += per_pair ? 2 : 1) {
      Real t0, t1;
      segment_bounds(i, steps_before, steps_after, t_closest, before, after, t0, t1);
      if (per_pair) {
        Real t2, t3;
        segment_bounds(i + 1, steps_before, steps_after, t_closest, before, after, t2, t3);
        FieldMoments field = field_at_point(atmosphere, previous_order,
                                            o + (Real(0.5) * (t0 + t3)) * d, sun_dir);
        Real3 p = o + (Real(0.5) * (t0 + t1)) * d;
        Real3 field_r, field_m;
        field_radiance(atmosphere, field, length(p), p, d, sun_dir, field_r, field_m);
        accumulate_segment_in(atmosphere, o, d, t0, t1, sun_dir, phase_r, phase_m, source_kind,
                              field_r, field_m, true, luminance, transmittance, f_ms);
        p = o + (Real(0.5) * (t2 + t3)) * d;
        field_radiance(atmosphere, field, length(p), p, d, sun_dir, field_r, field_m);
        accumulate_segment_in(atmosphere, o, d, t2, t3, sun_dir, phase_r, phase_m, source_kind,
                              field_r, field_m, true, luminance, transmittance, f_ms);
      } else {
        accumulate_segment(atmosphere, o, d, t0, t1, sun_dir, phase_r, phase_m, source_kind,
                           luminance, transmittance, f_ms);
      }
    }
  }
  if (ends_at_ground) {
    Real3 p = o + t_end * d;
    if (source_kind == kSourceNextOrder) {
      Real mu_s = clamp_cosine(dot(p, sun_dir) / length(p));
      luminance += transmittance * atmosphere.ground_albedo / kPi *
                   ground_order_lookup(atmosphere, mu_s);
    } else {
      luminance += transmittance * ground_radiance(atmosphere, p, sun_dir);
    }
  }
}

void integrate_scattering(IN(Atmosphere) atmosphere, IN(Real3) o, IN(Real3) d, Real t_start,
                          Real t_end, IN(Real3) sun_dir, int steps, int source_kind,
                          bool ends_at_ground, OUT(Real3) luminance, OUT(Real3) transmittance,
                          OUT(Real3) f_ms) {
  integrate_along(atmosphere, o, d, t_start, t_end, sun_dir, steps, source_kind, kFieldEachStep,
                  ends_at_ground, luminance, transmittance, f_ms);
}

// The ray o + t d (o inside the top sphere) up to the top boundary or the
// ground, whichever comes first.
void ray_extent_inside(IN(Atmosphere) atmosphere, IN(Real3) o, IN(Real3) d, OUT(Real) t_end,
                       OUT(bool) hits_ground) {
  Real t_near, t_far;
  ray_sphere(o, d, atmosphere.top_radius, t_near, t_far);
  t_end = max(t_far, Real(0.0));
  // Whether the ray goes down into the ground is decided from (r, mu), not
  // from the sign of a rounded intersection distance: from the ground
  // itself, a ray just above the horizon would otherwise end where it starts.
  Real r = length(o);
  Real mu = dot(o, d) / r;
  hits_ground = ray_intersects_ground(atmosphere, r, mu);
  if (hits_ground) t_end = min(t_end, distance_to_bottom_boundary(atmosphere, r, mu));
}
