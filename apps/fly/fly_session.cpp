#include "apps/fly/fly_session.h"

#include "atmosphere/gpu/registry.h"
#include "core/image_io.h"
#include "core/progress.h"
#include "gl/context.h"
#include "gl/driver_watch.h"
#include "sim/body_switch.h"
#include "sim/free_flight.h"
#include "sim/geodesy.h"
#include "sim/orbit_flight.h"
#include "sim/star_catalogue.h"
#include "sim/sun_ephemeris.h"
#include "terrain/ground.h"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace planet::apps {

namespace {

constexpr double kStep = 1.0 / 120.0;  // fixed simulation step, seconds
// The clock follows wall time, in as many fixed steps as a frame needs (at
// one frame a second, 120); only a stall longer than this (a suspended
// machine) is dropped rather than flown through.
constexpr double kLongestStallSeconds = 30.0;
constexpr double kRecordRate = 10.0;  // recorded keyframes (= capture frames) per second
// A technique's tables built between frames take as long a frame as the
// frame itself takes to draw (the window's rate halves while they are
// built), and at least this long: a quick frame does not stretch the build.
constexpr double kLeastBuildSlice = 0.05;
const std::array<const char*, 5> kBodies = {"earth", "mars", "asteroid", "moon", "eros"};

// "10:30 local solar time" from the sun's hour angle.
std::string solar_time_text(double hour_angle) {
  int minutes = int(std::lround(local_solar_hours(hour_angle) * 60.0)) % (24 * 60);
  return fmt::format("{:02d}:{:02d}", minutes / 60, minutes % 60);
}

}  // namespace

FlySession::FlySession(const FlyArgs& args, GLFWwindow* window, FlyInput& input, Hud& hud)
    : args_(args),
      window_(window),
      input_(input),
      hud_(hud),
      clock_(parse_utc(args.time, "--time")),
      step_(kStep),
      exposure_(args.exposure),
      technique_(args.technique) {
  parse_technique(technique_);
  error_model_ = load_error_model(args.error_model.empty() ? shipped_error_model_file()
                                                          : std::filesystem::path(args.error_model));
  renderer_ = std::make_unique<FrameRenderer>(std::max(1, int(args.width * args.render_scale)),
                                              std::max(1, int(args.height * args.render_scale)));
  // The edges as a capture draws them (a flight's default); but llvmpipe
  // shades each sample, and even with the light once a pixel the coverage's
  // samples doubled the surfaces' pass (121 against 62 ms a frame at 480 x
  // 270, the ascent): there the edges are smoothed in the image instead,
  // for a few ms.
  const bool software =
      std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))).find("llvmpipe") !=
      std::string::npos;
  FrameOptions options;
  options.antialiasing = args.antialiasing > 0 ? args.antialiasing
                         : software            ? 1
                                               : FlightScript().antialiasing;
  options.smooth_edges = args.antialiasing == 0 && software;
  // The sun glares as it does to an eye; a capture leaves it out unless asked.
  options.glare = true;
  // A window never waits for tiles: it draws parents while children load.
  options.terrain_wait_s = 0.0;
  options.stars = true;
  options.auto_exposure = args.auto_exposure;
  // Wall times cost the frame what overlap would have given it; only asked for.
  options.synchronous_timing = args.pass_table;
  ldr_framebuffer_ = make_framebuffer(renderer_->ldr_texture(), 0);
  std::optional<FlightScript> flight;
  if (!args.flight_file.empty()) {
    flight = load_flight_script(args.flight_file, terrain_ground());
    options.auto_exposure = flight->auto_exposure;
    options.stars = flight->stars;
  }
  renderer_->set_options(options);
  if (flight) {
    FlightScript script = std::move(*flight);
    technique_ = script.technique;
    if (!args.technique_given && !script.technique_named) {
      error_budget_ = args.error_budget > 0 ? args.error_budget
                                            : script.error_budget_percent.value_or(0.0);
    }
    exposure_ = script.exposure;
    load(script.body.file.string(), false);
    auto scripted = std::make_unique<ScriptedFlight>(std::move(script));
    scripted_ = scripted.get();
    controller_ = std::move(scripted);
  } else {
    if (!args.technique_given) error_budget_ = args.error_budget > 0 ? args.error_budget : 0.0;
    load(args.planet, true);
  }
}

bool FlySession::frame(double real_dt) {
  glfwPollEvents();
  if (glfwWindowShouldClose(window_)) return false;
  for (int key : input_.take_presses(hud_.has_keyboard())) handle_key(key);
  FlightInput input = input_.read(hud_.has_keyboard(), hud_.has_mouse());
  for (int i = step_.advance(real_dt, int(kLongestStallSeconds / kStep)); i > 0; --i) {
    // The clock runs at its scale; the pilot flies in real time (a paused
    // or fast clock changes the sun, not the controls).
    clock_.advance(kStep);
    controller_->step(kStep, clock_.utc(), input);
    if (scripted_) {
      if (scripted_->finished()) glfwSetWindowShouldClose(window_, GLFW_TRUE);
      exposure_ = scripted_->exposure();
      clock_.set(scripted_->utc());
    }
    ++steps_;
    if (recorder_ && steps_ % int(std::lround(1.0 / (kStep * kRecordRate))) == 0) {
      recorder_->add(camera(), clock_.elapsed(), renderer_->last_exposure());
    }
  }
  Camera cam = camera();
  glm::dvec3 sun = sun_dir();
  decision_.reset();
  if (governor_ && atmosphere_) {
    decision_ = governor_->decide(view_features(body_, *atmosphere_, cam.pos_body, sun));
    set_progress_observer([this](const std::string& line, double) {
      glfwSetWindowTitle(window_, fmt::format("{}: {}", kFlyTitle, line).c_str());
      glfwPollEvents();
    });
    switch_->apply(*decision_, *atmosphere_);
    set_progress_observer(nullptr);
  }
  if (handover_) advance_handover(real_dt);
  const auto draw_began = std::chrono::steady_clock::now();
  renderer_->set_star_orientation(body_from_icrf(body_, clock_.utc()));
  stats_ = renderer_->render(cam, sun, exposure_);
  tally_.add(stats_.passes);
  blit();
  apply(hud_.draw(hud_view(cam, sun, real_dt)));
  {
    DriverWait wait("showing the frame (swapping buffers)");
    glfwSwapBuffers(window_);
  }
  check_gl_errors("fly frame");
  draw_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - draw_began).count();
  return true;
}

void FlySession::advance_handover(double real_dt) {
  if (!handover_->advance(real_dt, std::max(kLeastBuildSlice, draw_seconds_))) {
    if (handover_->finished()) handover_.reset();
    return;
  }
  technique_ = handover_->choice();
  std::printf(
      "technique: %s (built in %.1f s while %d frames were drawn, %.1f s of it building; the "
      "longest frame %.2f s)\n",
      technique_.c_str(), handover_->wall_seconds(), handover_->frames_while_building(),
      handover_->build_seconds(), handover_->longest_frame_seconds());
  std::fflush(stdout);
}

double FlySession::ground_at(const Geodetic& place) const {
  return ground_height(renderer_->terrain()->surface(), *geodesy_, place);
}

Camera FlySession::camera() const {
  Camera c = controller_->camera();
  c.vertical_fov = glm::radians(args_.vertical_fov_deg);
  return c;
}

glm::dvec3 FlySession::sun_dir() const {
  if (scripted_) return scripted_->sun_dir_body();
  if (!body_.ephemeris.available()) return glm::dvec3(0, 0, 1);
  return sun_dir_body(body_.ephemeris, body_.rotation, clock_.utc());
}

// Gives the renderer the body with its atmosphere drawn by the current
// technique.
void FlySession::attach(const Body& body) {
  // A technique still being built was for the body before.
  handover_.reset();
  std::optional<AtmosphereModel> atmosphere;
  std::unique_ptr<AtmosphereTechnique> technique;
  if (body.has_atmosphere()) {
    atmosphere = load_atmosphere(body);
    technique = make_technique(technique_);
  }
  // A new body builds a new terrain, which takes the budget now set.
  FrameOptions options = renderer_->options();
  options.terrain.pixel_budget = double(lod_pixels_);
  renderer_->set_options(options);
  // A technique's first tables for a model (bruneton's take seconds) hold
  // the loop: their progress goes to the window's title, and the window
  // keeps answering the desktop (key presses wait in their queue).
  set_progress_observer([this](const std::string& line, double) {
    glfwSetWindowTitle(window_, fmt::format("{}: {}", kFlyTitle, line).c_str());
    glfwPollEvents();
  });
  renderer_->set_body(body, atmosphere, std::move(technique));
  set_progress_observer(nullptr);
  glfwSetWindowTitle(window_, kFlyTitle);
  atmosphere_ = atmosphere;
  body_ = body;
  // The governor starts over on each body, from the technique now drawn.
  switch_.reset();
  governor_.reset();
  if (error_budget_ > 0 && atmosphere) {
    GovernorSettings settings;
    settings.budget_percent = error_budget_;
    switch_.emplace(*renderer_, technique_);
    governor_.emplace(error_model_, settings, technique_);
  }
}

void FlySession::set_error_budget(double percent) {
  if (percent == error_budget_) return;
  error_budget_ = percent;
  // The governor chooses from the technique drawn now: a pick still being
  // built is dropped.
  if (percent > 0) handover_.reset();
  if (percent > 0 && governor_) {
    governor_->set_budget(percent);
  } else if (percent > 0 && atmosphere_) {
    // On: it starts from the technique drawn now.
    GovernorSettings settings;
    settings.budget_percent = percent;
    switch_.emplace(*renderer_, technique_);
    governor_.emplace(error_model_, settings, technique_);
  } else if (percent <= 0 && governor_) {
    // Off: its last choice draws on.
    if (!switch_->current().empty()) technique_ = switch_->current();
    renderer_->set_fade(nullptr, 0.0);
    governor_.reset();
    switch_.reset();
  }
  std::printf("error budget: %s\n", percent > 0 ? fmt::format("{:g} %", percent).c_str() : "off");
  std::fflush(stdout);
}

// A new body. From the command line, the pilot starts over the start
// place; a switch keeps the place, the height above the ground, the look
// and the local solar time (sim/body_switch.h); a script's body starts
// where the script puts it.
void FlySession::load(const std::string& name, bool from_args) {
  // A recording holds one body: it ends where the body changes.
  if (recorder_) toggle_recording();
  // Where the pilot was, taken before the new body's terrain replaces the
  // old one's.
  const bool switching = !from_args && geodesy_ != nullptr;
  Body was_body;
  Camera was_camera;
  double was_height = 0;
  if (switching) {
    was_body = body_;
    was_camera = camera();
    Geodetic g = geodesy_->geodetic_from_body(was_camera.pos_body);
    was_height = g.height - ground_at(g);
  }
  Body body = load_body(find_body_file(name));
  attach(body);
  body_ = body;
  geodesy_ = std::make_unique<Geodesy>(body.shape);
  body_key_ = name;
  scripted_ = nullptr;
  auto ground_fn = [this](const Geodetic& g) { return ground_at(g); };
  std::string kept;
  if (switching) {
    BodySwitch s = switch_body(was_body, was_camera, was_height, clock_.utc(), body, ground_fn);
    clock_.set(s.utc);
    auto free_flight = std::make_unique<FreeFlight>(body, s.camera);
    free_flight->set_ground(ground_fn);
    controller_ = std::move(free_flight);
    kept = fmt::format(
        "; kept from {}: lat {:.4f} lon {:.4f}, the height above the ground{}, local solar time "
        "{} (clock to {})",
        was_body.name, glm::degrees(s.place.lat), glm::degrees(s.place.lon),
        s.height_clamped ? fmt::format(" (clamped from {:.1f} m)", was_height) : std::string(),
        solar_time_text(s.sun_hour_angle), format_utc(s.utc));
  } else {
    // Heights count from the ground under the start place.
    Geodetic place{glm::radians(args_.lat_deg), glm::radians(args_.lon_deg), 0.0};
    place.height =
        ground_at(place) +
        (from_args ? args_.height_m : std::max(2.0, 1e-3 * body.shape.equatorial_radius));
    if (from_args && args_.orbit_inclination_deg >= 0) {
      KeplerOrbit orbit = circular_orbit_over(
          body, place, glm::radians(args_.orbit_inclination_deg), true, clock_.utc());
      auto orbit_flight = std::make_unique<OrbitFlight>(body, orbit, clock_.utc());
      orbit_flight->set_ground(ground_fn);
      controller_ = std::move(orbit_flight);
    } else {
      auto free_flight = std::make_unique<FreeFlight>(body, place, glm::radians(args_.heading_deg));
      free_flight->set_ground(ground_fn);
      controller_ = std::move(free_flight);
    }
  }
  // What the HUD will show: the camera's own height over the real ground.
  Geodetic at = geodesy_->geodetic_from_body(controller_->camera().pos_body);
  std::string light = switching || from_args ? "; " + light_up(at) : std::string();
  std::printf("body: %s, %.1f m above the ground (%.1f m above the ellipsoid)%s%s\n",
              body.name.c_str(), at.height - ground_at(at), at.height, kept.c_str(), light.c_str());
  std::fflush(stdout);
}

// Below the horizon a fixed exposure shows a black screen: there the
// exposure follows the scene (and the stars come out), unless the command
// line fixed it.
std::string FlySession::light_up(const Geodetic& place) {
  double elevation = horizon_angles(sun_dir(), place.lat, place.lon).elevation;
  Daylight light = daylight(elevation, body_.has_atmosphere());
  std::string text =
      fmt::format("sun {:.1f} deg: {}", glm::degrees(elevation), daylight_name(light));
  if (light != Daylight::kDay && !renderer_->options().auto_exposure && !args_.exposure_given) {
    FrameOptions options = renderer_->options();
    options.auto_exposure = true;
    renderer_->set_options(options);
    text += ", the exposure follows the scene (auto)";
  }
  return text;
}

// A new technique: same body, same place. The one drawn now draws on while
// the new one's tables are built between frames; then it fades in. Another
// pick before that drops the build and starts on the new pick.
void FlySession::set_technique(const std::string& name) {
  // A technique picked by hand wins over the governor: its last choice
  // draws until the pick is built.
  error_budget_ = 0;
  if (governor_) {
    if (!switch_->current().empty()) technique_ = switch_->current();
    renderer_->set_fade(nullptr, 0.0);
    governor_.reset();
    switch_.reset();
  }
  handover_.reset();
  if (!atmosphere_ || name == technique_) {
    // Nothing to build: an airless body draws no sky.
    technique_ = name;
    std::printf("technique: %s\n", name.c_str());
    std::fflush(stdout);
    return;
  }
  handover_ = std::make_unique<TechniqueHandover>(*renderer_, name, *atmosphere_);
}

void FlySession::handle_key(int key) {
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window_, GLFW_TRUE);
  if (key == GLFW_KEY_B) {
    size_t i = 0;
    while (i < kBodies.size() && body_key_ != kBodies[i]) ++i;
    load(kBodies[(i + 1) % kBodies.size()], false);
  }
  if (key == GLFW_KEY_T) {
    // The next after the one being built, if any.
    auto names = technique_names();
    const std::string& from = handover_ ? handover_->choice() : technique_;
    auto it = std::find(names.begin(), names.end(), parse_technique(from).name);
    size_t i = it == names.end() ? 0 : size_t(it - names.begin());
    set_technique(names[(i + 1) % names.size()]);
  }
  if (key == GLFW_KEY_F12) screenshot();
  if (key == GLFW_KEY_F9) toggle_recording();
  if (key == GLFW_KEY_P) clock_.set_scale(clock_.scale() > 0 ? 0.0 : 1.0);
  if (key == GLFW_KEY_H) hud_.toggle();
}

HudView FlySession::hud_view(const Camera& cam, const glm::dvec3& sun, double real_dt) const {
  HudView v;
  Geodetic g = geodesy_->geodetic_from_body(cam.pos_body);
  HorizonAngles sun_angles = horizon_angles(sun, g.lat, g.lon);
  v.height_m = g.height - ground_at(g);
  v.height_ellipsoid_m = g.height;
  v.speed_m_s = controller_->speed();
  v.lat_deg = glm::degrees(g.lat);
  v.lon_deg = glm::degrees(g.lon);
  v.sun_elevation_deg = glm::degrees(sun_angles.elevation);
  v.daylight = daylight_name(daylight(sun_angles.elevation, body_.has_atmosphere()));
  LookAngles look = look_angles(glm::conjugate(glm::quat_cast(geodesy_->body_from_enu(g))) *
                                cam.body_from_camera);
  v.heading_deg = glm::degrees(look.heading);
  v.pitch_deg = glm::degrees(look.pitch);
  v.frame_ms = real_dt * 1e3;
  for (const auto& p : stats_.passes) {
    if (p.skipped) continue;
    v.passes += p.reused ? fmt::format("{:<24} reused\n", p.pass)
                         : fmt::format("{:<24} {:.2f} ms\n", p.pass, p.gpu_ms);
    (p.reused ? v.passes_reused : v.passes_ran) += 1;
  }
  v.gpu_ms = stats_.total_gpu_ms();
  v.body_name = body_.name;
  // To the second: the HUD's first line holds the sun too.
  v.utc = format_utc(clock_.utc()).substr(0, 19) + "Z";
  v.recording = recorder_ != nullptr;
  v.clock_locked = recorder_ != nullptr || scripted_ != nullptr;
  v.bodies.assign(kBodies.begin(), kBodies.end());
  // Every technique at its default, then at each of its other quality
  // points (bruneton:cheap, oneil:chapter, ...).
  v.techniques.clear();
  for (const TechniqueEntry& entry : technique_registry()) {
    v.techniques.push_back(entry.name);
    for (const auto& point : entry.quality_points) {
      if (point.first != "default") v.techniques.push_back(entry.name + ":" + point.first);
    }
  }
  v.body = body_key_;
  v.technique = switch_ && !switch_->current().empty() ? switch_->current() : technique_;
  if (handover_) {
    v.technique_build = handover_->choice();
    v.technique_build_step = handover_->status();
    v.technique_build_fraction = handover_->fraction();
  }
  v.error_budget = error_budget_;
  if (decision_) {
    const GovernorDecision& d = *decision_;
    v.governor = d.governed
                     ? fmt::format("governor: {} {:.1f} % {:.0f} ms{}\n  best {} {:.2f} % {:.0f} ms",
                                   d.choice, 100 * d.chosen.error, d.chosen.cost_ms,
                                   d.fading_from.empty() ? std::string()
                                                         : fmt::format(" (fading {})", d.fading_from),
                                   d.most_accurate.choice, 100 * d.most_accurate.error,
                                   d.most_accurate.cost_ms)
                     : "governor: " + d.why;
    v.governor_why = d.why;
  }
  double day_start = std::floor((clock_.utc() + 43200.0) / 86400.0) * 86400.0 - 43200.0;
  v.hours_utc = (clock_.utc() - day_start) / 3600.0;
  v.time_scale = clock_.scale();
  v.auto_exposure = renderer_->options().auto_exposure;
  v.exposure = renderer_->last_exposure();
  v.lod_pixels = lod_pixels_;
  v.terrain_shadows = renderer_->options().terrain_shadows;
  v.stars = renderer_->options().stars;
  v.glare = renderer_->options().glare;
  return v;
}

void FlySession::apply(const HudChanges& c) {
  if (c.body) load(*c.body, false);
  if (c.technique) set_technique(*c.technique);
  if (c.error_budget) set_error_budget(*c.error_budget);
  if (c.hours_utc) {
    // Time of day: moves the clock within the current UTC day.
    double day_start = std::floor((clock_.utc() + 43200.0) / 86400.0) * 86400.0 - 43200.0;
    clock_.set(day_start + *c.hours_utc * 3600.0);
  }
  if (c.time_scale) clock_.set_scale(*c.time_scale);
  if (c.exposure) exposure_ = *c.exposure;
  if (c.lod_pixels) {
    lod_pixels_ = *c.lod_pixels;
    if (renderer_->terrain()) renderer_->terrain()->set_pixel_budget(double(lod_pixels_));
  }
  // Most frames change no box: the renderer's options are set only when one does.
  if (!c.terrain_shadows && !c.stars && !c.glare && !c.auto_exposure) return;
  FrameOptions options = renderer_->options();
  if (c.terrain_shadows) options.terrain_shadows = *c.terrain_shadows;
  if (c.stars) options.stars = *c.stars;
  if (c.glare) options.glare = *c.glare;
  if (c.auto_exposure) {
    // Off: the slider starts from what the frames were shown with.
    if (!*c.auto_exposure && options.auto_exposure) exposure_ = renderer_->last_exposure();
    options.auto_exposure = *c.auto_exposure;
  }
  renderer_->set_options(options);
}

void FlySession::blit() {
  int w, h;
  glfwGetFramebufferSize(window_, &w, &h);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, w, h);
  glBlitNamedFramebuffer(ldr_framebuffer_.id(), 0, 0, 0, renderer_->width(), renderer_->height(), 0,
                         0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

void FlySession::screenshot() {
  std::filesystem::create_directories(args_.out_dir);
  std::string stem = fmt::format("screenshot_{:04d}", screenshots_++);
  auto base = std::filesystem::path(args_.out_dir) / stem;
  write_exr(base.string() + ".exr", renderer_->width(), renderer_->height(), renderer_->read_hdr());
  write_png(base.string() + ".png", renderer_->width(), renderer_->height(), renderer_->read_ldr());
  std::printf("screenshot: %s.png and .exr\n", base.string().c_str());
  std::fflush(stdout);
}

void FlySession::toggle_recording() {
  if (!recorder_) {
    clock_.rebase_to_millisecond();
    steps_ = 0;
    recorder_ = std::make_unique<FlightRecorder>(body_key_, technique_, renderer_->width(),
                                                 renderer_->height(), args_.vertical_fov_deg,
                                                 kRecordRate, clock_.epoch());
    recorder_->add(camera(), clock_.elapsed(), renderer_->last_exposure());
    std::printf("recording\n");
  } else {
    std::filesystem::create_directories(args_.out_dir);
    auto file =
        std::filesystem::path(args_.out_dir) / fmt::format("flight_{:04d}.json", flights_++);
    recorder_->write(file);
    std::printf("recorded %d frames into %s (replay: planet capture --flight %s)\n",
                recorder_->frames(), file.string().c_str(), file.string().c_str());
    recorder_.reset();
  }
  std::fflush(stdout);
}

}  // namespace planet::apps
