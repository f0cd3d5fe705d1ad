// planet probe moon: the Moon's light over a place on Earth at a UTC
// instant: where it stands, its phase, and its illuminance above the air
// and on the ground (terrain/moonlight.h).
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "atmosphere/model.h"
#include "atmosphere/reference/columns.h"
#include "atmosphere/reference/medium.h"
#include "atmosphere/spectrum.h"
#include "core/error.h"
#include "sim/body.h"
#include "sim/ephemeris.h"
#include "sim/geodesy.h"
#include "sim/sun_ephemeris.h"
#include "sim/utc_time.h"
#include "terrain/moonlight.h"
#include "terrain/terrain_config.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

namespace planet::apps {

namespace {

struct ProbeMoonArgs {
  double lat_deg = 0, lon_deg = 0, height_m = 0;
  std::string time;
};

// 683 lm/W times the integral of the CIE 1931 y-bar over a spectrum given
// at the medium's wavelengths (trapezoids between them).
double illuminance_lux(const Medium& medium, const std::vector<double>& irradiance) {
  double sum = 0;
  for (size_t i = 0; i + 1 < medium.channels.size(); ++i) {
    const double a = medium.channels[i].wavelength_nm, b = medium.channels[i + 1].wavelength_nm;
    sum +=
        0.5 * (b - a) * (cie1931_xyz(a).y * irradiance[i] + cie1931_xyz(b).y * irradiance[i + 1]);
  }
  return 683.0 * sum;
}

void run(const ProbeMoonArgs& args) {
  checked_latitude_deg(args.lat_deg, "--lat");
  checked_longitude_deg(args.lon_deg, "--lon");
  const Body earth = load_body(find_body_file("earth"));
  const Body moon_body = load_body(find_body_file("moon"));
  const UtcSeconds utc = parse_utc(args.time, "--time");
  const TerrainConfig moon_terrain = parse_terrain(moon_body);
  if (!moon_terrain.regolith) {
    throw InputError(fmt::format("{}: terrain has no \"regolith\": the Moon's light needs its law",
                                 moon_body.file.string()));
  }
  const double lat = glm::radians(args.lat_deg), lon = glm::radians(args.lon_deg);
  const glm::dvec3 observer = Geodesy(earth.shape).body_from_geodetic({lat, lon, args.height_m});
  const glm::dvec3 sun =
      sun_dir_body(earth.ephemeris, earth.rotation, utc) * glm::length(sun_pos_gcrs(utc));
  const glm::dvec3 moon = *companion_pos_body(earth.ephemeris, earth.rotation, utc);
  const double moon_radius = moon_body.shape.equatorial_radius;
  const Moonlight light = moonlight(*moon_terrain.regolith, moon_radius, sun, moon, observer);
  const HorizonAngles moon_at = horizon_angles(glm::normalize(moon - observer), lat, lon);
  const HorizonAngles sun_at = horizon_angles(glm::normalize(sun), lat, lon);

  // The sun's spectrum, the model's, at the Earth's mean distance; the
  // Moon's light follows it (the Moon taken as grey).
  const AtmosphereModel model = load_atmosphere(earth);
  const Medium medium = make_medium(model, ReferenceMode::kSpectral);
  const double au_scale = std::pow(kAuMetres / glm::length(sun - observer), 2.0);
  std::vector<double> above(medium.channels.size()), below(medium.channels.size());
  // The air between the place and the Moon, from the bottom of the
  // atmosphere plus the place's height (a sphere: the Moon's elevation is
  // the zenith cosine's complement).
  const ColumnTable columns(medium, 2, 2);
  const double r = model.bottom_radius + args.height_m, mu = std::sin(moon_at.elevation);
  const glm::dvec3 column = columns.integrate_to_top(r, mu);
  for (size_t i = 0; i < medium.channels.size(); ++i) {
    const MediumChannel& c = medium.channels[i];
    above[i] = c.solar_irradiance * au_scale * light.over_sunlight;
    below[i] = moon_at.elevation > 0 ? above[i] * std::exp(-optical_depth(c, column)) : 0.0;
  }
  const double lux_above = illuminance_lux(medium, above);
  const double lux_below = illuminance_lux(medium, below);
  std::printf("time        %s\n", format_utc(utc).c_str());
  std::printf("place       lat %.4f deg, lon %s, %.0f m up\n", args.lat_deg,
              longitude_text(args.lon_deg, 4).c_str(), args.height_m);
  std::printf("Moon        elevation %.3f deg, azimuth %.3f deg, %.0f km away\n",
              glm::degrees(moon_at.elevation), glm::degrees(moon_at.azimuth),
              glm::length(moon - observer) / 1000.0);
  std::printf("sun         elevation %.3f deg\n", glm::degrees(sun_at.elevation));
  std::printf("phase       %.3f deg (0: full), %.1f %% of the disk lit\n",
              glm::degrees(light.phase), 100.0 * light.illuminated_fraction);
  std::printf("brightness  %.4f of a white disk facing the sun (Hapke's law, %s)\n",
              light.disk_brightness, moon_body.file.filename().string().c_str());
  std::printf("moonlight   %.4g of the sunlight, above the air\n", light.over_sunlight);
  std::printf("illuminance %.4f lux above the air, facing the Moon\n", lux_above);
  if (moon_at.elevation > 0) {
    std::printf("            %.4f lux under the air, facing the Moon (%s's model)\n", lux_below,
                earth.name.c_str());
    std::printf("            %.4f lux on level ground\n", lux_below * mu);
  } else {
    std::printf("            0 lux on the ground: the Moon is below the horizon\n");
  }
}

}  // namespace

void add_probe_moon_command(CLI::App& probe) {
  auto args = std::make_shared<ProbeMoonArgs>();
  CLI::App* cmd = probe.add_subcommand(
      "moon", "The Moon's light over a place on Earth: its phase and illuminance");
  cmd->add_option("--lat", args->lat_deg, "Geodetic latitude, degrees")->required();
  cmd->add_option("--lon", args->lon_deg, "Longitude east, degrees (-180 to 360)")->required();
  cmd->add_option("--height", args->height_m, "Metres above the ellipsoid")
      ->check(within(0.0, 1e5))
      ->capture_default_str();
  cmd->add_option("--time", args->time, "UTC, e.g. 2024-04-23T23:49:00Z")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
