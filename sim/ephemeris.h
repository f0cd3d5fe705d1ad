#pragma once
// Where the Sun and the Moon really are, from ERFA (the BSD edition of the
// IAU's SOFA): the Earth's orbit (VSOP87-based eraEpv00, a few
// milliarcseconds here), the Moon's place (eraMoon98, Meeus's ELP2000-82
// truncation: a few arcseconds, a few km in distance), and the Earth's
// orientation (IAU 2006/2000A precession-nutation and the Earth rotation
// angle). Positions are geocentric, in metres, in the GCRS (the ICRS's axes
// carried to the Earth's centre) or in the Earth-fixed frame that the body
// files' "earth" rotation stands for (the ITRS without polar motion: under
// 0.5 arcsec, 15 m on the ground). docs/bodies.md#the-sun-and-the-moon.
#include "sim/utc_time.h"

#include <glm/glm.hpp>

namespace planet {

// The astronomical unit, metres (IAU 2012).
inline constexpr double kAuMetres = 149597870700.0;

// TT - UT1 in seconds. 1990 to 2026: the observed values (IERS, yearly,
// interpolated; 68.8 s in August 2017, 69.2 s in April 2024); 2026 on: held
// at the last, since it now changes by well under a second a year; before
// 1990 and after 2050: Espenak and Meeus's polynomials (NASA, Five
// Millennium Canon, 2006), which join the table within a second.
double delta_t(UtcSeconds utc);

// The two-part Julian dates ERFA takes, for a UTC instant.
struct ErfaDates {
  double tt1 = 0, tt2 = 0;    // terrestrial time
  double ut11 = 0, ut12 = 0;  // UT1 = TT - delta_t
};
ErfaDates erfa_dates(UtcSeconds utc);

// Rotates GCRS vectors into the Earth-fixed frame (ITRS, polar motion left
// out): the CIO-based chain, IAU 2006/2000A (eraC2i06a, eraEra00).
glm::dmat3 itrs_from_gcrs(UtcSeconds utc);

// The Sun's apparent geocentric position, metres: where its light that
// reaches Earth at `utc` comes from, with the light's travel time (499 s)
// and the aberration of the Earth's motion (20 arcsec). Its length is the
// true distance.
glm::dvec3 sun_pos_gcrs(UtcSeconds utc);

// The Moon's geocentric position, metres, as seen at `utc` (its place 1.3 s
// earlier, when the light left it: the aberration of the Earth's own motion
// cancels against the Moon's shared part of it).
glm::dvec3 moon_pos_gcrs(UtcSeconds utc);

}  // namespace planet
