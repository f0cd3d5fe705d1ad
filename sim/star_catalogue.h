#pragma once
// The bright stars behind every sky: a catalogue read from
// data/stars/bright_stars.csv (the Yale Bright Star Catalogue to magnitude
// 6), each star a direction in the ICRF and a V magnitude, turned into a
// body's frame by its spin.
#include "sim/body.h"
#include "sim/utc_time.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

namespace planet {

struct Star {
  int hr = 0;                    // the catalogue's number
  glm::dvec3 dir_icrf{0, 0, 1};  // unit vector
  double magnitude = 0;          // V
};

// The star's irradiance per unit of the sun's, both seen from 1 AU: the
// sun's V magnitude is -26.74 (Willmer 2018), so a star of magnitude m
// gives 10^(-0.4 (m + 26.74)) of it.
double star_irradiance_per_sun(double magnitude);

// Reads a catalogue in the shipped format (comment lines start with '#',
// then the header "hr,ra_hours,dec_deg,vmag" and one star a line).
// InputError naming the file and line for anything else.
std::vector<Star> read_star_catalogue(const std::filesystem::path& path);
// The shipped catalogue, read once.
const std::vector<Star>& bright_stars();

// Rotates ICRF directions into the body-fixed frame at `utc`; a body
// without a spin keeps the ICRF's axes.
glm::dmat3 body_from_icrf(const Body& body, UtcSeconds utc);

}  // namespace planet
