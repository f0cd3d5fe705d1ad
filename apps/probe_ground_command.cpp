// planet probe ground: the terrain's height under a place, so that a flight
// script can start a given distance above the ground rather than above the
// ellipsoid.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "sim/body.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"
#include "terrain/terrain_surface.h"

#include <glm/gtc/constants.hpp>

#include <cstdio>
#include <memory>

namespace planet::apps {

namespace {

struct ProbeGroundArgs {
  std::string planet = "earth";
  double lat_deg = 0, lon_deg = 0;
};

void run(const ProbeGroundArgs& args) {
  checked_latitude_deg(args.lat_deg, "--lat");
  checked_longitude_deg(args.lon_deg, "--lon");
  Body body = load_body(find_body_file(args.planet));
  Geodesy geodesy(body.shape);
  TerrainSurface surface(body.shape, parse_terrain(body));
  glm::dvec3 ground =
      ground_point(surface, geodesy, {glm::radians(args.lat_deg), glm::radians(args.lon_deg), 0.0});
  std::printf("%s at lat %.6f deg, lon %s\n", body.name.c_str(), args.lat_deg,
              longitude_text(args.lon_deg, 6).c_str());
  std::printf("ground  %.3f m above the ellipsoid (a flight script's height_m)\n",
              geodesy.geodetic_from_body(ground).height);
  std::printf("radius  %.3f m from the body's centre\n", glm::length(ground));
}

}  // namespace

void add_probe_ground_command(CLI::App& probe) {
  auto args = std::make_shared<ProbeGroundArgs>();
  CLI::App* cmd = probe.add_subcommand("ground", "The terrain's height under a place");
  cmd->add_option("--planet", args->planet, body_option_help())->capture_default_str();
  cmd->add_option("--lat", args->lat_deg, "Latitude, degrees (-90 to 90)")->required();
  cmd->add_option("--lon", args->lon_deg, "Longitude east, degrees (-180 to 360)")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
