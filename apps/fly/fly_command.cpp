// planet fly: a window onto a body, flown with mouse and keyboard, with a
// HUD to change body, atmosphere technique, time and exposure. The options
// and their checks are here; the flight is fly_session.h.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/fly/fly_hud.h"
#include "apps/fly/fly_input.h"
#include "apps/fly/fly_session.h"
#include "atmosphere/gpu/registry.h"
#include "core/error.h"
#include "gl/context.h"
#include "governor/governor.h"
#include "sim/free_flight.h"
#include "sim/kepler.h"
#include "sim/orbit_flight.h"
#include "terrain/ground.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numeric>
#include <vector>

namespace planet::apps {

namespace {

void run(const FlyArgs& args) {
  // Fail on bad input before a window opens.
  if (!(args.render_scale > 0.05 && args.render_scale <= 2.0)) {
    throw InputError(fmt::format("--render-scale: {} is not within 0.05 to 2", args.render_scale));
  }
  if (args.antialiasing < 0 || args.antialiasing > 16 ||
      (args.antialiasing & (args.antialiasing - 1)) != 0) {
    throw InputError(fmt::format(
        "--antialiasing: {} samples a pixel: give 1 (none), 2, 4, 8 or 16, or 0 for the default",
        args.antialiasing));
  }
  if (!args.flight_file.empty()) load_flight_script(args.flight_file, terrain_ground());
  checked_latitude_deg(args.lat_deg, "--lat");
  checked_longitude_deg(args.lon_deg, "--lon");
  if (args.orbit_inclination_deg > 180.0) {
    throw InputError("--orbit-inclination: must be 0 to 180 deg");
  }
  parse_utc(args.time, "--time");
  Body body = load_body(find_body_file(args.planet));
  if (args.height_m < FreeFlight::kClearance) {
    throw InputError(
        fmt::format("--height: {:g} m is below the ground's clearance: heights count "
                    "from the ground, and the camera stays at least {:g} m above it",
                    args.height_m, FreeFlight::kClearance));
  }
  if (!std::isnan(args.error_budget)) checked_error_budget(args.error_budget, "--error-budget");
  if (args.error_budget > 0 && args.technique_given) {
    std::fprintf(stderr, "planet: --technique %s wins over --error-budget: the governor is off\n",
                 args.technique.c_str());
  }
  load_error_model(args.error_model.empty() ? shipped_error_model_file()
                                            : std::filesystem::path(args.error_model));
  try {
    parse_technique(args.technique);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--technique: {}", e.what()));
  }
  if (args.orbit_inclination_deg >= 0) {
    Geodetic place{glm::radians(args.lat_deg), glm::radians(args.lon_deg), args.height_m};
    try {
      circular_orbit_over(body, place, glm::radians(args.orbit_inclination_deg), true,
                          parse_utc(args.time, "--time"));
    } catch (const InputError& e) {
      throw InputError(fmt::format("--orbit-inclination: {}", e.what()));
    }
  }
  ContextOptions options;
  options.width = args.width;
  options.height = args.height;
  options.title = kFlyTitle;
  auto context = GlContext::create_window(options);
  FlyInput input(context->window());  // first: the HUD's backend chains to its callback
  Hud hud(context->window());
  FlySession session(args, context->window(), input, hud);
  auto begun = std::chrono::steady_clock::now(), last = begun;
  int frames = 0;
  std::pair<int, int> hud_size{0, 0};
  std::vector<double> frame_seconds;
  for (;;) {
    auto now = std::chrono::steady_clock::now();
    double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    if (frames > 0) frame_seconds.push_back(dt);  // the frame before this call's
    if (!session.frame(dt)) break;
    ++frames;
    hud_size = std::max(hud_size, hud.size());
  }
  double seconds = std::chrono::duration<double>(last - begun).count();
  // The slowest 1 % of frames (at least one), their mean: the stutter a
  // mean frame rate hides.
  std::sort(frame_seconds.begin(), frame_seconds.end(), std::greater<>());
  const size_t slowest = std::max<size_t>(1, frame_seconds.size() / 100);
  const size_t counted = std::min(slowest, frame_seconds.size());
  const double slowest_s =
      std::accumulate(frame_seconds.begin(), frame_seconds.begin() + long(counted), 0.0) /
      double(slowest);
  std::printf(
      "flew %d frames in %.1f s (%.1f frames/s, the slowest 1 %% of frames %.0f ms each); the "
      "HUD took at most %d x %d px of the %d x %d window\n",
      frames, seconds, frames / std::max(seconds, 1e-9), 1e3 * slowest_s, hud_size.first,
      hud_size.second, args.width, args.height);
  if (args.pass_table) {
    std::printf("each pass, its mean wall and GPU time over the frames it ran:\n%s",
                session.passes().table().c_str());
  } else {
    std::printf(
        "each pass, its mean GPU time over the frames it ran (timer queries: on "
        "llvmpipe they miss what runs in the calling thread):\n%s",
        session.passes().summary().c_str());
  }
}

}  // namespace

void add_fly_command(CLI::App& app) {
  auto args = std::make_shared<FlyArgs>();
  CLI::App* cmd = app.add_subcommand("fly", "Fly over a body in a window (mouse, keyboard, HUD)");
  cmd->add_option("--planet", args->planet, body_option_help())->capture_default_str();
  cmd->add_option("--lat", args->lat_deg, "Start latitude, degrees (-90 to 90)")
      ->capture_default_str();
  cmd->add_option("--lon", args->lon_deg, "Start longitude east, degrees (-180 to 360)")
      ->capture_default_str();
  cmd->add_option("--height", args->height_m, "Start height above the ground, metres")
      ->capture_default_str();
  cmd->add_option("--heading", args->heading_deg, "Start heading, degrees from north")
      ->capture_default_str();
  cmd->add_option("--orbit-inclination", args->orbit_inclination_deg,
                  "Start in a circular orbit at --height with this inclination, degrees");
  cmd->add_option("--time", args->time, "Start time, UTC")->capture_default_str();
  cmd->add_option("--technique", args->technique, "Atmosphere technique (wins over --error-budget)")
      ->capture_default_str()
      ->each([args](const std::string&) { args->technique_given = true; });
  add_schedule_option(*cmd);
  cmd->add_option("--error-budget", args->error_budget,
                  "Let the governor choose the technique each frame: the cheapest whose "
                  "predicted error is within PCT percent (also a HUD slider)");
  cmd->add_option("--error-model", args->error_model,
                  "The governor's table (default data/lab/error_model.json)");
  cmd->add_option("--exposure", args->exposure,
                  "Exposure (where the sun is down it follows the scene unless given)")
      ->check(positive())
      ->capture_default_str()
      ->each([args](const std::string&) { args->exposure_given = true; });
  cmd->add_flag("--auto-exposure", args->auto_exposure,
                "Each frame's exposure from its own mean luminance, up to a dark-adapted eye's "
                "(also a HUD box)");
  cmd->add_option(
      "--size",
      [args](const CLI::results_t& r) {
        return std::sscanf(r[0].c_str(), "%dx%d", &args->width, &args->height) == 2 &&
               args->width > 0 && args->height > 0;
      },
      "Window size WxH (960x540)");
  cmd->add_option("--flight", args->flight_file,
                  "Fly a flight script (data/flights/*.json) as capture would; ends with it");
  cmd->add_option("--render-scale", args->render_scale,
                  "Rendered size relative to the window (0.5 halves it; screenshots are this size)")
      ->capture_default_str();
  cmd->add_option("--antialiasing", args->antialiasing,
                  "Samples a pixel for the edges of the ground against the sky: 1 (none), 2, 4, "
                  "8, 16; 0: as a capture draws them (4), but on llvmpipe (where 4 cost twice "
                  "the surfaces' pass) 1 with the image's edges smoothed (FXAA)")
      ->capture_default_str();
  cmd->add_flag(
      "--pass-table", args->pass_table,
      "At the end, each pass's mean wall and GPU time and how often it ran, was "
      "reused or skipped (each pass then waits for the GL: the frame rate drops a little)");
  cmd->add_option("--out", args->out_dir, "Folder for screenshots and recorded flights")
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
