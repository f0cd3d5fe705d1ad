#pragma once
// The Mars24 algorithm: Mars solar time and the sun's position as seen from
// Mars, after Allison and McEwen (2000), "A post-Pathfinder evaluation of
// areocentric solar coordinates", Planet. Space Sci. 48, 215-235, in the
// form of NASA GISS's "Mars24 Algorithm and Worked Examples". Step labels
// (B-1, C-2, ...) are those of that page.
#include "sim/utc_time.h"

namespace planet {

struct MarsSun {
  double ls = 0;                 // areocentric solar longitude Ls, radians in [0, 2 pi)
  double equation_of_time = 0;   // radians of rotation (true minus mean sun)
  double mean_solar_time_h = 0;  // MST (coordinated Mars time) at the prime meridian, hours
  double subsolar_lon_east = 0;  // radians in (-pi, pi]
  double subsolar_lat = 0;       // planetographic, radians
  double sun_distance_au = 0;
};

MarsSun mars_sun(UtcSeconds utc);

// Local true solar time at an east longitude (radians), hours in [0, 24).
double mars_local_true_solar_time_h(const MarsSun& sun, double lon_east);

}  // namespace planet
