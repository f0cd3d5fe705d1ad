#include "sim/ephemeris.h"

#include <erfa.h>

#include <array>
#include <cmath>

namespace planet {

namespace {

constexpr double kJulianDaySeconds = 86400.0;
constexpr double kJ2000 = 2451545.0;  // JD of 2000-01-01T12:00:00
constexpr double kLightMetresPerSecond = 299792458.0;
constexpr double kAuLightSeconds = kAuMetres / kLightMetresPerSecond;

// TT - UT1 on January 1 of each year from 1990 to 2026, seconds: the IERS's
// observed values (32.184 s + TAI - UTC - (UT1 - UTC)), rounded to 0.01 s.
constexpr int kTableFirstYear = 1990;
constexpr std::array<double, 37> kDeltaT = {
    56.86, 57.57, 58.31, 59.12, 59.98, 60.78, 61.63, 62.29, 62.97, 63.47,  // 1990-1999
    63.83, 64.09, 64.30, 64.47, 64.57, 64.69, 64.85, 65.15, 65.46, 65.78,  // 2000-2009
    66.07, 66.32, 66.60, 66.91, 67.28, 67.64, 68.10, 68.59, 68.97, 69.22,  // 2010-2019
    69.36, 69.36, 69.29, 69.20, 69.18, 69.14, 69.10};                      // 2020-2026

// Espenak and Meeus's long-term parabola (Morrison and Stephenson 2004).
double delta_t_long_term(double year) {
  double u = (year - 1820.0) / 100.0;
  return -20.0 + 32.0 * u * u;
}

// Espenak and Meeus (NASA's Five Millennium Canon, 2006): their polynomials
// for the years before the table.
double delta_t_before_table(double y) {
  if (y >= 1986.0) {
    double t = y - 2000.0;
    return 63.86 +
           t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + t * 0.00002373599))));
  }
  if (y >= 1961.0) {
    double t = y - 1975.0;
    return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
  }
  if (y >= 1941.0) {
    double t = y - 1950.0;
    return 29.07 + 0.407 * t - t * t / 233.0 + t * t * t / 2547.0;
  }
  return delta_t_long_term(y);
}

// The Julian date of a UTC instant split as ERFA likes it (J2000 + days),
// which keeps the fraction of the day exact to microseconds.
double days_since_j2000(UtcSeconds utc) { return utc / kJulianDaySeconds; }

glm::dvec3 to_glm(const double v[3]) { return {v[0], v[1], v[2]}; }

}  // namespace

double delta_t(UtcSeconds utc) {
  // The decimal year, near enough for a quantity that moves under 1 s a year.
  double year = 2000.0 + (utc / kJulianDaySeconds + 0.5) / 365.2425;
  const double last_year = kTableFirstYear + double(kDeltaT.size() - 1);
  if (year < kTableFirstYear) return delta_t_before_table(year);
  if (year >= last_year) {
    // Joined to the table's last value: a jump there would move the ground
    // under an eclipse's shadow by kilometres.
    return kDeltaT.back() + delta_t_long_term(year) - delta_t_long_term(last_year);
  }
  double f = year - kTableFirstYear;
  auto i = size_t(f);
  return kDeltaT[i] + (f - double(i)) * (kDeltaT[i + 1] - kDeltaT[i]);
}

ErfaDates erfa_dates(UtcSeconds utc) {
  ErfaDates d;
  d.tt1 = d.ut11 = kJ2000;
  d.tt2 = days_since_j2000(utc + tt_minus_utc(utc));
  d.ut12 = d.tt2 - delta_t(utc) / kJulianDaySeconds;
  return d;
}

glm::dmat3 itrs_from_gcrs(UtcSeconds utc) {
  ErfaDates d = erfa_dates(utc);
  double rc2i[3][3], rpom[3][3], rc2t[3][3];
  eraC2i06a(d.tt1, d.tt2, rc2i);
  eraIr(rpom);  // polar motion left out (under 0.5 arcsec)
  eraC2tcio(rc2i, eraEra00(d.ut11, d.ut12), rpom, rc2t);
  // ERFA's matrices are row-major; glm's constructor takes columns.
  glm::dmat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[c][r] = rc2t[r][c];
  return m;
}

glm::dvec3 sun_pos_gcrs(UtcSeconds utc) {
  ErfaDates d = erfa_dates(utc);
  // TDB - TT is under 2 ms: TT serves for both.
  double pvh[2][3], pvb[2][3];
  eraEpv00(d.tt1, d.tt2, pvh, pvb);
  // The Sun seen from the Earth's centre: minus the Earth's heliocentric
  // position. In the light's 499 s of travel the Sun moves 6 km about the
  // barycentre (0.01 arcsec): its geometric place serves.
  glm::dvec3 sun_au = -to_glm(pvh[0]);
  double distance_au = glm::length(sun_au);
  // Aberration from the Earth's barycentric velocity (au/day into units of
  // c), with the Sun's gravitational term in ERFA's own formula.
  double v[3], pnat[3], ppr[3];
  for (int i = 0; i < 3; ++i) {
    v[i] = pvb[1][i] * kAuLightSeconds / kJulianDaySeconds;
    pnat[i] = sun_au[i] / distance_au;
  }
  double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  eraAb(pnat, v, distance_au, std::sqrt(1.0 - v2), ppr);
  return to_glm(ppr) * distance_au * kAuMetres;
}

glm::dvec3 moon_pos_gcrs(UtcSeconds utc) {
  ErfaDates d = erfa_dates(utc);
  double pv[2][3];
  eraMoon98(d.tt1, d.tt2, pv);
  // One pass of light time: 1.3 s, in which the Moon moves 1.3 km; the
  // second pass would move it by millimetres.
  double light_days = eraPm(pv[0]) * kAuLightSeconds / kJulianDaySeconds;
  eraMoon98(d.tt1, d.tt2 - light_days, pv);
  return to_glm(pv[0]) * kAuMetres;
}

}  // namespace planet
