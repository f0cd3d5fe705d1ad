// planet probe transmittance | sky: the atmosphere model's quantities at a
// height above the bottom of the atmosphere, with their units.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "atmosphere/math/shared_math.h"
#include "atmosphere/reference/path_tracer.h"
#include "core/error.h"
#include "core/progress.h"
#include "lab/scene.h"
#include "sim/body.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace planet::apps {

namespace {

struct ProbeArgs {
  std::string planet = "earth", mode = "rgb";
  double height_m = 0;
  double zenith_deg = 0, view_zenith_deg = 0, view_azimuth_deg = 0, sun_zenith_deg = 0;
  int paths = 100000;
  int max_order = 0;  // 0: every order
};

AtmosphereModel load_model(const std::string& planet, Body& body) {
  body = load_body(find_body_file(planet));
  return load_atmosphere(body);
}

void run_transmittance(const ProbeArgs& args) {
  Body body;
  AtmosphereModel model = load_model(args.planet, body);
  Medium medium = make_medium(model, parse_reference_mode(args.mode));
  double r = model.bottom_radius + args.height_m;
  double mu = std::cos(glm::radians(args.zenith_deg));
  std::printf(
      "%s: transmittance from height %g m (r = %.0f m) at view zenith %g deg to the top "
      "of the atmosphere (%.0f m)\n",
      body.name.c_str(), args.height_m, r, args.zenith_deg, model.top_radius);
  shared::Atmosphere a = shared::to_shared(model);
  if (shared::ray_intersects_ground(a, r, mu)) {
    std::printf("the ray meets the ground %.0f m away: transmittance 0 (the planet's shadow)\n",
                shared::distance_to_bottom_boundary(a, r, mu));
    return;
  }
  double length = shared::distance_to_top_boundary(a, r, mu);
  std::printf("path length %.1f m; optical depth by the trapezoid rule, 20000 steps\n", length);
  std::printf("%15s %15s %15s\n", "wavelength_nm", "optical_depth", "transmittance");
  for (const MediumChannel& c : medium.channels) {
    // The medium's coefficients at this channel, integrated along the ray.
    const int steps = 20000;
    double dt = length / steps, tau = 0;
    for (int i = 0; i <= steps; ++i) {
      double t = i * dt;
      double r_t = std::sqrt(t * t + 2.0 * r * mu * t + r * r);
      double w = (i == 0 || i == steps) ? 0.5 : 1.0;
      tau += w * medium.at(c, r_t - model.bottom_radius).extinction() * dt;
    }
    std::printf("%15.0f %15.6g %15.6g\n", c.wavelength_nm, tau, std::exp(-tau));
  }
}

void run_sky(const ProbeArgs& args) {
  const int max_order = checked_max_order(args.max_order, "probe sky --max-order");
  Body body;
  AtmosphereModel model = load_model(args.planet, body);
  Medium medium = make_medium(model, parse_reference_mode(args.mode));
  glm::dvec3 origin(0, 0, model.bottom_radius + std::max(args.height_m, 1.0));
  double vz = glm::radians(args.view_zenith_deg), va = glm::radians(args.view_azimuth_deg);
  double sz = glm::radians(args.sun_zenith_deg);
  // Azimuths from the sun's: the sun lies in the x-z plane.
  glm::dvec3 view(std::sin(vz) * std::cos(va), std::sin(vz) * std::sin(va), std::cos(vz));
  glm::dvec3 sun(std::sin(sz), 0.0, std::cos(sz));
  std::printf(
      "%s: sky radiance at height %g m, view zenith %g deg, azimuth %g deg from the sun, "
      "sun zenith %g deg\n",
      body.name.c_str(), args.height_m, args.view_zenith_deg, args.view_azimuth_deg,
      args.sun_zenith_deg);
  std::printf(
      "path-traced reference, %d paths per wavelength, %s, ground "
      "albedo %g; radiance in W m^-2 sr^-1 nm^-1 (+- one standard error)\n",
      args.paths,
      max_order > 0 ? fmt::format("scattering orders 1 to {}", max_order).c_str()
                         : "all scattering orders",
      model.ground_albedo.g);
  std::printf("%15s %15s %15s\n", "wavelength_nm", "radiance", "std_error");
  glm::dvec3 rgb(0.0);
  TraceOptions options;
  options.max_order = max_order;
  // Seconds at 100000 paths: a wait that shows its progress.
  Progress progress("probe sky", double(medium.channels.size()), "wavelength");
  progress.update(0);
  const ColumnTable table(medium);
  for (size_t i = 0; i < medium.channels.size(); ++i) {
    RadianceEstimate e =
        estimate_radiance(table, i, origin, view, sun, options, args.paths, 0x5eed + i);
    progress.update(double(i + 1));
    std::printf("%15.0f %15.6g %15.2g\n", medium.channels[i].wavelength_nm, e.mean, e.std_error);
    rgb += e.mean * medium.channels[i].rgb_weight;
  }
  progress.finish();
  std::printf("linear sRGB (%s mode): %.6g %.6g %.6g\n", args.mode.c_str(), rgb.r, rgb.g, rgb.b);
}

}  // namespace

void add_probe_atmosphere_commands(CLI::App& probe) {
  auto args = std::make_shared<ProbeArgs>();
  CLI::App* t = probe.add_subcommand("transmittance",
                                     "Transmittance to the top of the atmosphere per wavelength");
  t->add_option("--planet", args->planet, body_option_help())->capture_default_str();
  t->add_option("--height", args->height_m, "Metres above the bottom of the atmosphere")
      ->check(within(0.0, 1e9));
  t->add_option("--zenith", args->zenith_deg, "View zenith angle, degrees")
      ->check(within(0.0, 180.0));
  t->add_option("--mode", args->mode, "rgb or spectral")->capture_default_str();
  t->callback([args] { run_transmittance(*args); });

  CLI::App* s = probe.add_subcommand("sky", "Sky radiance in one direction, from the reference");
  s->add_option("--planet", args->planet, body_option_help())->capture_default_str();
  s->add_option("--height", args->height_m, "Metres above the bottom of the atmosphere")
      ->check(within(0.0, 1e9));
  s->add_option("--view-zenith", args->view_zenith_deg, "View zenith angle, degrees")
      ->check(within(0.0, 180.0));
  s->add_option("--view-azimuth", args->view_azimuth_deg, "View azimuth from the sun's, degrees")
      ->check(within(-360.0, 360.0));
  s->add_option("--sun-zenith", args->sun_zenith_deg, "Sun zenith angle, degrees")
      ->check(within(0.0, 180.0));
  s->add_option("--paths", args->paths, "Paths per wavelength")
      ->check(within(100, 100000000))
      ->capture_default_str();
  s->add_option("--mode", args->mode, "rgb or spectral")->capture_default_str();
  s->add_option("--max-order", args->max_order,
                "Sum only the first N orders of scattering (1: single scattering alone; "
                "default: every order)");
  s->callback([args] { run_sky(*args); });
}

}  // namespace planet::apps
