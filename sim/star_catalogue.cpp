#include "sim/star_catalogue.h"

#include "core/data_paths.h"
#include "core/error.h"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

namespace planet {

double star_irradiance_per_sun(double magnitude) {
  return std::pow(10.0, -0.4 * (magnitude + 26.74));
}

namespace {

// The fields of one line, each a number; false for anything else.
bool parse_star(const std::string& line, Star& star) {
  double field[4];
  const char* p = line.c_str();
  for (int i = 0; i < 4; ++i) {
    char* end = nullptr;
    errno = 0;
    field[i] = std::strtod(p, &end);
    if (end == p || errno != 0 || !std::isfinite(field[i])) return false;
    p = end;
    if (i < 3 && *p++ != ',') return false;
  }
  while (*p == ' ' || *p == '\r') ++p;
  if (*p != '\0') return false;
  const double ra_hours = field[1], dec_deg = field[2];
  if (field[0] < 1 || field[0] > 1e6 || field[0] != std::floor(field[0])) return false;
  if (ra_hours < 0 || ra_hours >= 24 || std::abs(dec_deg) > 90) return false;
  if (field[3] < -2 || field[3] > 10) return false;  // none is brighter than Sirius
  const double ra = ra_hours * glm::pi<double>() / 12.0, dec = glm::radians(dec_deg);
  star.hr = int(field[0]);
  star.dir_icrf = {std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec)};
  star.magnitude = field[3];
  return true;
}

}  // namespace

std::vector<Star> read_star_catalogue(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read the star catalogue", path.string()));
  std::vector<Star> stars;
  std::string line;
  bool header = false;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line.rfind("hr,ra_hours,dec_deg,vmag", 0) != 0) {
        throw InputError(fmt::format("{}:{}: expected the header hr,ra_hours,dec_deg,vmag",
                                     path.string(), number));
      }
      header = true;
      continue;
    }
    Star star;
    if (!parse_star(line, star)) {
      throw InputError(fmt::format(
          "{}:{}: a star is HR number, hours of right ascension in [0, 24), degrees of "
          "declination in [-90, 90] and a magnitude in [-2, 10], comma-separated; got \"{}\"",
          path.string(), number, line.substr(0, 80)));
    }
    stars.push_back(star);
  }
  if (in.bad()) throw InputError(fmt::format("{}: read error", path.string()));
  if (stars.empty()) throw InputError(fmt::format("{}: no stars", path.string()));
  return stars;
}

const std::vector<Star>& bright_stars() {
  static const std::vector<Star> stars =
      read_star_catalogue(data_dir() / "stars" / "bright_stars.csv");
  return stars;
}

glm::dmat3 body_from_icrf(const Body& body, UtcSeconds utc) {
  if (!body.has_rotation) return glm::dmat3(1.0);
  return body.rotation.body_from_inertial(utc) * body.rotation.inertial_from_icrf();
}

}  // namespace planet
