#pragma once
// Eclipses by geometry: the Sun and the Moon where ERFA puts them
// (sim/ephemeris.h), the Moon's shadow cones against the Earth's WGS84
// ellipsoid, and the Earth's shadow at the Moon's distance. The figures are
// the ones NASA publishes for each eclipse (Espenak and Meeus, Five
// Millennium Canon): greatest eclipse, the central path's width and duration
// there, and a lunar eclipse's contact times. docs/bodies.md#eclipses.
#include "sim/geodesy.h"
#include "sim/utc_time.h"

#include <optional>
#include <string>

namespace planet {

struct EclipseConstants {
  // The Earth: WGS84.
  double earth_radius = 6378137.0;  // a, metres
  double earth_flattening = 1.0 / 298.257223563;
  // The Sun's radius, metres (959.63 arcsec at 1 au, as NASA takes it).
  double sun_radius = 696.0e6;
  // The Moon's radius in Earth radii. The Canon takes k = 0.272281 for the
  // umbra (the valleys of the limb, which let the last light through) and
  // 0.272488 for the penumbra; k = 0.2725076 is the IAU's mean radius,
  // which NASA takes for the Moon's disk in a lunar eclipse.
  double moon_k_umbra = 0.272281;
  double moon_k_penumbra = 0.272488;
  double moon_k_mean = 0.2725076;
  // Danjon's enlargement of the Earth's shadow for its atmosphere, which
  // NASA's lunar Canon uses: the Earth's radius grows by 1/85 and the
  // shadow's radii are 1.01 pi_moon + pi_sun -/+ s_sun (1.01 being
  // (1 + 1/85) times 0.99834, the Earth's radius at latitude 45 deg in
  // equatorial radii). Chauvenet's older rule enlarges the radii themselves
  // by 2 %.
  double danjon_factor = 1.01;
};

struct SolarEclipse {
  // The instant the shadow's axis passes nearest the Earth's centre.
  UtcSeconds greatest = 0;
  // That distance in Earth radii, positive with the axis north of the
  // centre (NASA's gamma).
  double gamma = 0;
  // Whether the axis meets the ellipsoid; the figures below hold only then.
  bool central = false;
  bool total = false;           // total, else annular, at the point below
  Geodetic point;               // where the axis meets the ground then
  double sun_altitude = 0;      // radians, at that point
  double sun_azimuth = 0;       // radians, clockwise from north
  double path_width = 0;        // metres, across the path's centre line
  double central_duration = 0;  // seconds of totality (or annularity) there
};

struct LunarEclipse {
  UtcSeconds greatest = 0;  // the Moon nearest the shadow's centre
  double gamma = 0;         // that distance in Earth radii, + north
  double umbral_magnitude = 0, penumbral_magnitude = 0;
  // Contacts with the penumbra (P1, P4) and the umbra (U1 to U4); absent
  // where the eclipse does not reach that phase.
  std::optional<UtcSeconds> p1, u1, u2, u3, u4, p4;
};

struct Eclipse {
  std::optional<SolarEclipse> solar;
  std::optional<LunarEclipse> lunar;
};

// The eclipse of the Sun or of the Moon whose greatest phase falls on the
// UTC day that starts at `day` (neither, where that day has none).
Eclipse find_eclipse(UtcSeconds day, const EclipseConstants& c = {});

// The solar eclipse whose greatest phase lies within 3 hours of `near`;
// none where the Moon's penumbra misses the Earth.
std::optional<SolarEclipse> solar_eclipse(UtcSeconds near, const EclipseConstants& c = {});
// The lunar eclipse whose greatest phase lies within 3 hours of `near`;
// none where the Moon misses the penumbra.
std::optional<LunarEclipse> lunar_eclipse(UtcSeconds near, const EclipseConstants& c = {});

}  // namespace planet
