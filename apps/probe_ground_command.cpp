// planet probe ground: the terrain's height under a place, so that a flight
// script can start a given distance above the ground rather than above the
// ellipsoid.
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
  Body body = load_body(find_body_file(args.planet));
  Geodesy geodesy(body.shape);
  TerrainSurface surface(body.shape, parse_terrain(body));
  glm::dvec3 ground =
      ground_point(surface, geodesy, {glm::radians(args.lat_deg), glm::radians(args.lon_deg), 0.0});
  std::printf("%s at lat %.6f deg, lon %.6f deg\n", body.name.c_str(), args.lat_deg, args.lon_deg);
  std::printf("ground  %.3f m above the ellipsoid (a flight script's height_m)\n",
              geodesy.geodetic_from_body(ground).height);
  std::printf("radius  %.3f m from the body's centre\n", glm::length(ground));
}

}  // namespace

void add_probe_ground_command(CLI::App& probe) {
  auto args = std::make_shared<ProbeGroundArgs>();
  CLI::App* cmd = probe.add_subcommand("ground", "The terrain's height under a place");
  cmd->add_option("--planet", args->planet, "Body name or file (earth, mars, asteroid)")
      ->capture_default_str();
  cmd->add_option("--lat", args->lat_deg, "Latitude, degrees")
      ->required()
      ->check(CLI::Range(-90.0, 90.0));
  cmd->add_option("--lon", args->lon_deg, "Longitude east, degrees")
      ->required()
      ->check(CLI::Range(-180.0, 180.0));
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
