// planet probe sun: where the sun stands over a place at a UTC instant.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "core/error.h"
#include "sim/body.h"
#include "sim/geodesy.h"
#include "sim/mars24.h"
#include "sim/sun_ephemeris.h"
#include "sim/utc_time.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cstdio>
#include <memory>

namespace planet::apps {

namespace {

struct ProbeSunArgs {
  std::string planet = "earth";
  double lat_deg = 0, lon_deg = 0;
  std::string time;
};

std::string clock_text(double hours) {
  int seconds = int(std::lround(hours * 3600.0)) % 86400;
  return fmt::format("{:02d}:{:02d}:{:02d}", seconds / 3600, (seconds / 60) % 60, seconds % 60);
}

void run(const ProbeSunArgs& args) {
  checked_latitude_deg(args.lat_deg, "--lat");
  checked_longitude_deg(args.lon_deg, "--lon");
  Body body = load_body(find_body_file(args.planet));
  UtcSeconds utc = parse_utc(args.time, "--time");
  if (!body.ephemeris.available()) {
    throw InputError(fmt::format("{}: {} has no \"ephemeris\"", body.file.string(), body.name));
  }
  double lat = glm::radians(args.lat_deg), lon = glm::radians(args.lon_deg);
  glm::dvec3 sun = sun_dir_body(body.ephemeris, body.rotation, utc);
  HorizonAngles a = horizon_angles(sun, lat, lon);
  std::printf("body       %s (%s ephemeris)\n", body.name.c_str(), body.ephemeris.name().c_str());
  std::printf("time       %s\n", format_utc(utc).c_str());
  std::printf("place      lat %.4f deg, lon %s\n", args.lat_deg,
              longitude_text(args.lon_deg, 4).c_str());
  std::printf("elevation  %.4f deg  (geometric, no refraction)\n", glm::degrees(a.elevation));
  std::printf("azimuth    %.4f deg  (clockwise from north)\n", glm::degrees(a.azimuth));
  double sub_lat = std::asin(glm::clamp(sun.z, -1.0, 1.0));
  double sub_lon = std::atan2(sun.y, sun.x);
  std::printf("subsolar   lat %.4f deg, lon %.4f deg east\n", glm::degrees(sub_lat),
              glm::degrees(sub_lon));
  if (body.ephemeris.model == SunEphemeris::Model::kMars24) {
    MarsSun m = mars_sun(utc);
    double ltst = mars_local_true_solar_time_h(m, lon);
    std::printf("Ls         %.4f deg\n", glm::degrees(m.ls));
    std::printf("LTST       %s  (local true solar time, %.5f h)\n", clock_text(ltst).c_str(), ltst);
    std::printf("MTC        %s  (mean solar time at the prime meridian)\n",
                clock_text(m.mean_solar_time_h).c_str());
    std::printf("distance   %.5f AU\n", m.sun_distance_au);
  } else if (body.ephemeris.model == SunEphemeris::Model::kEarth) {
    EarthSun e = earth_sun(utc);
    double ra = glm::degrees(e.right_ascension);
    if (ra < 0) ra += 360.0;
    std::printf("RA/Dec     %.4f deg / %.4f deg (apparent, of date)\n", ra,
                glm::degrees(e.declination));
    std::printf("distance   %.6f AU\n", e.distance_au);
  }
  if (auto other = companion_pos_body(body.ephemeris, body.rotation, utc)) {
    // Seen from the place itself: the Moon's parallax reaches a degree.
    glm::dvec3 place = Geodesy(body.shape).body_from_geodetic({lat, lon, 0.0});
    HorizonAngles o = horizon_angles(glm::normalize(*other - place), lat, lon);
    std::printf("%-10s elevation %.4f deg, azimuth %.4f deg, %.0f km from the centre\n",
                companion_name(body.ephemeris), glm::degrees(o.elevation), glm::degrees(o.azimuth),
                glm::length(*other) / 1000.0);
  }
}

}  // namespace

void add_probe_sun_command(CLI::App& probe) {
  auto args = std::make_shared<ProbeSunArgs>();
  CLI::App* cmd = probe.add_subcommand("sun", "The sun's elevation and azimuth over a place");
  cmd->add_option("--planet", args->planet, body_option_help())->capture_default_str();
  cmd->add_option("--lat", args->lat_deg, "Geodetic latitude, degrees")->required();
  cmd->add_option("--lon", args->lon_deg, "Longitude east, degrees (-180 to 360)")->required();
  cmd->add_option("--time", args->time, "UTC, e.g. 2026-06-21T12:00:00Z")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
