#pragma once
// Two-body motion: an elliptic Kepler orbit propagated exactly by Kepler's
// equation (Vallado 2013, "Fundamentals of Astrodynamics", alg. 2 and 9),
// from classical elements or from a state vector, in the body's inertial
// equatorial frame (see BodyRotation).
#include "sim/body.h"
#include "sim/geodesy.h"
#include "sim/utc_time.h"

#include <glm/glm.hpp>

namespace planet {

struct StateVector {
  glm::dvec3 pos{0.0};  // metres
  glm::dvec3 vel{0.0};  // metres per second
};

struct OrbitalElements {
  double semi_major_axis = 0;  // metres
  double eccentricity = 0;     // [0, 1)
  double inclination = 0;      // radians
  double ascending_node = 0;   // right ascension of the ascending node, radians
  double periapsis_arg = 0;    // argument of periapsis, radians
  double mean_anomaly = 0;     // at the epoch, radians
};

class KeplerOrbit {
 public:
  KeplerOrbit() = default;
  // Throws InputError for a state that is not a bound orbit.
  static KeplerOrbit from_state(const StateVector& state, double mu, double epoch);
  static KeplerOrbit from_elements(const OrbitalElements& elements, double mu, double epoch);

  // The state `time` seconds after J2000 (any time; seconds of the epoch's
  // time scale).
  StateVector state_at(double time) const;
  double period() const;
  double mu() const { return mu_; }
  double semi_major_axis() const { return a_; }
  double eccentricity() const { return e_; }

 private:
  double mu_ = 0, a_ = 0, e_ = 0, mean_anomaly0_ = 0, epoch_ = 0;
  glm::dvec3 p_{1, 0, 0}, q_{0, 1, 0};  // toward periapsis, and 90 deg ahead in the plane
};

// Specific orbital energy and angular momentum of a state.
double orbital_energy(const StateVector& s, double mu);
glm::dvec3 angular_momentum(const StateVector& s);

// A circular orbit through a geodetic place at `utc`: height as given,
// inclination (radians) to the body's equator, heading north or south
// across that place. The body must have a "gm_m3_s2"; the inclination must
// reach the place's latitude.
KeplerOrbit circular_orbit_over(const Body& body, const Geodetic& place, double inclination,
                                bool northbound, UtcSeconds utc);

// Body-fixed position and velocity (relative to the turning body) of an
// inertial state at `utc`.
StateVector body_state(const Body& body, const StateVector& inertial, UtcSeconds utc);

}  // namespace planet
