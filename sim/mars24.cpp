#include "sim/mars24.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <array>
#include <cmath>

namespace planet {

namespace {

double deg_sin(double deg) { return std::sin(glm::radians(deg)); }
double deg_cos(double deg) { return std::cos(glm::radians(deg)); }
double wrap(double x, double period) { return x - period * std::floor(x / period); }

}  // namespace

MarsSun mars_sun(UtcSeconds utc) {
  // days since J2000 in terrestrial time.
  const double dt_j2000 = (utc + tt_minus_utc(utc)) / 86400.0;
  const double jd_tt = 2451545.0 + dt_j2000;
  // B-1, B-2: mean anomaly and the angle of the fictitious mean sun, degrees.
  const double m = 19.3871 + 0.52402073 * dt_j2000;
  const double alpha_fms = 270.3871 + 0.524038496 * dt_j2000;
  // B-3: perturbations by Jupiter, Earth and Venus.
  static constexpr std::array<double, 7> kA = {0.0071, 0.0057, 0.0039, 0.0037,
                                               0.0021, 0.0020, 0.0018};
  static constexpr std::array<double, 7> kTau = {2.2353, 2.7543, 1.1177, 15.7866,
                                                 2.1354, 2.4694, 32.8493};
  static constexpr std::array<double, 7> kPhi = {49.409, 168.173, 191.837, 21.736,
                                                 15.704, 95.528,  49.095};
  double pbs = 0;
  for (size_t i = 0; i < kA.size(); ++i) {
    pbs += kA[i] * deg_cos(0.985626 * dt_j2000 / kTau[i] + kPhi[i]);
  }
  // B-4: the equation of the centre, v - M.
  const double v_minus_m = (10.691 + 3.0e-7 * dt_j2000) * deg_sin(m) + 0.623 * deg_sin(2 * m) +
                           0.050 * deg_sin(3 * m) + 0.005 * deg_sin(4 * m) +
                           0.0005 * deg_sin(5 * m) + pbs;
  // B-5.
  const double ls = wrap(alpha_fms + v_minus_m, 360.0);
  // C-1: equation of time, degrees.
  const double eot =
      2.861 * deg_sin(2 * ls) - 0.071 * deg_sin(4 * ls) + 0.002 * deg_sin(6 * ls) - v_minus_m;
  // C-2: coordinated Mars time (mean solar time at the prime meridian).
  const double mst = wrap(24.0 * ((jd_tt - 2451549.5) / 1.0274912517 + 44796.0 - 0.0009626), 24.0);
  // C-5: the subsolar point's west longitude; the true sun is over the
  // meridian where the local true solar time is noon.
  const double subsolar_west = wrap(mst * 15.0 + eot + 180.0, 360.0);
  // D-1: planetographic solar declination.
  const double dec = glm::degrees(std::asin(0.42565 * deg_sin(ls))) + 0.25 * deg_sin(ls);
  // D-2: heliocentric distance.
  const double r = 1.52367934 * (1.00436 - 0.09309 * deg_cos(m) - 0.004336 * deg_cos(2 * m) -
                                 0.00031 * deg_cos(3 * m) - 0.00003 * deg_cos(4 * m));
  MarsSun sun;
  sun.ls = glm::radians(ls);
  sun.equation_of_time = glm::radians(eot);
  sun.mean_solar_time_h = mst;
  sun.subsolar_lon_east = std::remainder(glm::radians(-subsolar_west), 2.0 * glm::pi<double>());
  sun.subsolar_lat = glm::radians(dec);
  sun.sun_distance_au = r;
  return sun;
}

double mars_local_true_solar_time_h(const MarsSun& sun, double lon_east) {
  // C-3, C-4 with west longitude = -east longitude.
  double lmst = sun.mean_solar_time_h + glm::degrees(lon_east) / 15.0;
  return wrap(lmst + glm::degrees(sun.equation_of_time) / 15.0, 24.0);
}

}  // namespace planet
