// planet fly: a window onto a body, flown with mouse and keyboard, with a
// Dear ImGui HUD to change body, atmosphere technique, time and exposure.
#include "apps/commands.h"
#include "atmosphere/gpu/technique.h"
#include "core/error.h"
#include "core/image_io.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/body.h"
#include "sim/flight_recorder.h"
#include "sim/free_flight.h"
#include "sim/orbit_flight.h"
#include "sim/scripted_flight.h"
#include "sim/sun_ephemeris.h"
#include "sim/utc_time.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>

#include <glm/gtc/constants.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

namespace planet::apps {

namespace {

constexpr double kStep = 1.0 / 120.0;  // fixed simulation step, seconds
constexpr double kRecordRate = 10.0;   // recorded keyframes (= capture frames) per second
const std::array<const char*, 3> kBodies = {"earth", "mars", "asteroid"};
const std::array<double, 6> kTimeScales = {0.0, 1.0, 10.0, 100.0, 1000.0, 10000.0};

// Key presses as they arrive: a frame on a software renderer can take a
// second, longer than a tap, so polling the key state would miss them.
std::vector<int> g_key_presses;
void on_key(GLFWwindow*, int key, int, int action, int) {
  if (action == GLFW_PRESS) g_key_presses.push_back(key);
}

struct FlyArgs {
  std::string planet = "earth", technique = "raymarch", time = "2026-06-21T10:00:00Z";
  double lat_deg = 46.55, lon_deg = 7.98, height_m = 2.0, heading_deg = 90.0;
  double orbit_inclination_deg = -1;
  int width = 960, height = 540;
  double render_scale = 0.5;  // of the window; llvmpipe is slow at full size
  double exposure = 8.0, vertical_fov_deg = 60.0;
  std::string out_dir = ".";
  std::string flight_file;  // fly a script instead of the start place
};

class FlySession {
 public:
  FlySession(const FlyArgs& args, GLFWwindow* window)
      : args_(args),
        window_(window),
        clock_(parse_utc(args.time, "--time")),
        exposure_(args.exposure),
        technique_(args.technique) {
    auto names = technique_names();
    if (std::find(names.begin(), names.end(), technique_) == names.end()) {
      throw InputError(
          fmt::format("--technique: '{}' is not one of {}", technique_, fmt::join(names, ", ")));
    }
    renderer_ = std::make_unique<FrameRenderer>(std::max(1, int(args.width * args.render_scale)),
                                                std::max(1, int(args.height * args.render_scale)));
    // A window never waits for tiles: it draws parents while children load.
    renderer_->set_terrain_wait(0.0);
    if (!args.flight_file.empty()) {
      FlightScript script = load_flight_script(args.flight_file);
      technique_ = script.technique;
      exposure_ = script.exposure;
      load(script.body.file.string(), false);
      auto scripted = std::make_unique<ScriptedFlight>(std::move(script));
      scripted_ = scripted.get();
      controller_ = std::move(scripted);
    } else {
      load(args.planet, true);
    }
  }

  // One frame of the program: input, fixed steps, render, HUD. False to quit.
  bool frame(double real_dt) {
    glfwPollEvents();
    if (glfwWindowShouldClose(window_)) return false;
    handle_keys();
    FlightInput input = read_input();
    // Up to half a second of steps per frame: the simulation keeps real time
    // on a slow renderer, and a stall (a window drag) is dropped.
    for (int i = step_.advance(real_dt, 60); i > 0; --i) {
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
        recorder_->add(camera(), clock_.elapsed(), exposure_);
      }
    }
    Camera cam = camera();
    glm::dvec3 sun = sun_dir();
    stats_ = renderer_->render(cam, sun, exposure_);
    blit();
    hud(cam, sun, real_dt);
    glfwSwapBuffers(window_);
    check_gl_errors("fly frame");
    return true;
  }

 private:
  Camera camera() const {
    Camera c = controller_->camera();
    c.vertical_fov = glm::radians(args_.vertical_fov_deg);
    return c;
  }

  glm::dvec3 sun_dir() const {
    if (scripted_) return scripted_->sun_dir_body();
    if (!body_.ephemeris.available()) return glm::dvec3(0, 0, 1);
    return sun_dir_body(body_.ephemeris, body_.rotation, clock_.utc());
  }

  // Gives the renderer the body with its atmosphere drawn by the current
  // technique.
  void attach(const Body& body) {
    std::optional<AtmosphereModel> atmosphere;
    std::unique_ptr<AtmosphereTechnique> technique;
    if (body.has_atmosphere()) {
      atmosphere = load_atmosphere(body);
      technique = make_technique(technique_);
    }
    // A new body builds a new terrain, which takes the budget now set.
    TerrainOptions terrain;
    terrain.pixel_budget = double(lod_pixels_);
    renderer_->set_terrain_options(terrain);
    renderer_->set_body(body, atmosphere, std::move(technique));
  }

  // A new body: the pilot starts over the start place (a few km up unless
  // it came from the command line).
  void load(const std::string& name, bool from_args) {
    // A recording holds one body: it ends where the body changes.
    if (recorder_) toggle_recording();
    Body body = load_body(find_body_file(name));
    attach(body);
    body_ = body;
    body_key_ = name;
    Geodetic place{glm::radians(args_.lat_deg), glm::radians(args_.lon_deg), args_.height_m};
    if (!from_args) place.height = std::max(2.0, 1e-3 * body.shape.equatorial_radius);
    scripted_ = nullptr;
    if (from_args && args_.orbit_inclination_deg >= 0) {
      KeplerOrbit orbit = circular_orbit_over(
          body, place, glm::radians(args_.orbit_inclination_deg), true, clock_.utc());
      controller_ = std::make_unique<OrbitFlight>(body, orbit, clock_.utc());
    } else {
      controller_ = std::make_unique<FreeFlight>(body, place, glm::radians(args_.heading_deg));
    }
    std::printf("body: %s\n", body.name.c_str());
    std::fflush(stdout);
  }

  // A new technique: same body, same place.
  void set_technique(const std::string& name) {
    technique_ = name;
    attach(body_);
    std::printf("technique: %s\n", name.c_str());
    std::fflush(stdout);
  }

  void handle_keys() {
    std::vector<int> keys;
    keys.swap(g_key_presses);
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    for (int key : keys) handle_key(key);
  }

  void handle_key(int key) {
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window_, GLFW_TRUE);
    if (key == GLFW_KEY_B) {
      size_t i = 0;
      while (i < kBodies.size() && body_key_ != kBodies[i]) ++i;
      load(kBodies[(i + 1) % kBodies.size()], false);
    }
    if (key == GLFW_KEY_T) {
      auto names = technique_names();
      auto it = std::find(names.begin(), names.end(), technique_);
      size_t i = it == names.end() ? 0 : size_t(it - names.begin());
      set_technique(names[(i + 1) % names.size()]);
    }
    if (key == GLFW_KEY_F12) screenshot();
    if (key == GLFW_KEY_F9) toggle_recording();
    if (key == GLFW_KEY_P) clock_.set_scale(clock_.scale() > 0 ? 0.0 : 1.0);
  }

  FlightInput read_input() {
    FlightInput in;
    if (ImGui::GetIO().WantCaptureKeyboard) return in;
    auto key = [&](int k) { return glfwGetKey(window_, k) == GLFW_PRESS ? 1.0 : 0.0; };
    in.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_R) - key(GLFW_KEY_F),
               key(GLFW_KEY_W) - key(GLFW_KEY_S)};
    in.turn = {key(GLFW_KEY_UP) - key(GLFW_KEY_DOWN), key(GLFW_KEY_LEFT) - key(GLFW_KEY_RIGHT),
               key(GLFW_KEY_E) - key(GLFW_KEY_Q)};
    in.boost = key(GLFW_KEY_LEFT_SHIFT) > 0 ? 10.0 : 1.0;
    // Mouse: drag with the left button to look around.
    double x, y;
    glfwGetCursorPos(window_, &x, &y);
    if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS &&
        !ImGui::GetIO().WantCaptureMouse) {
      in.turn.y += std::clamp(-(x - mouse_x_) * 0.2, -1.0, 1.0);
      in.turn.x += std::clamp(-(y - mouse_y_) * 0.2, -1.0, 1.0);
    }
    mouse_x_ = x;
    mouse_y_ = y;
    return in;
  }

  void blit() {
    if (!read_fbo_) glCreateFramebuffers(1, &read_fbo_);
    glNamedFramebufferTexture(read_fbo_, GL_COLOR_ATTACHMENT0, renderer_->ldr_texture(), 0);
    int w, h;
    glfwGetFramebufferSize(window_, &w, &h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    glBlitNamedFramebuffer(read_fbo_, 0, 0, 0, renderer_->width(), renderer_->height(), 0, 0, w, h,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
  }

  void screenshot() {
    std::filesystem::create_directories(args_.out_dir);
    std::string stem = fmt::format("screenshot_{:04d}", screenshots_++);
    auto base = std::filesystem::path(args_.out_dir) / stem;
    write_exr(base.string() + ".exr", renderer_->width(), renderer_->height(),
              renderer_->read_hdr());
    write_png(base.string() + ".png", renderer_->width(), renderer_->height(),
              renderer_->read_ldr());
    std::printf("screenshot: %s.png and .exr\n", base.string().c_str());
    std::fflush(stdout);
  }

  void toggle_recording() {
    if (!recorder_) {
      clock_.rebase_to_millisecond();
      steps_ = 0;
      recorder_ = std::make_unique<FlightRecorder>(body_key_, technique_, renderer_->width(),
                                                   renderer_->height(), args_.vertical_fov_deg,
                                                   kRecordRate, clock_.epoch());
      recorder_->add(camera(), clock_.elapsed(), exposure_);
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

  void hud(const Camera& cam, const glm::dvec3& sun, double real_dt) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::Begin("planet");
    Geodesy geodesy(body_.shape);
    Geodetic g = geodesy.geodetic_from_body(cam.pos_body);
    HorizonAngles sun_angles = horizon_angles(sun, g.lat, g.lon);
    std::string passes;
    for (const auto& p : stats_.passes) passes += fmt::format(" {} {:.2f}", p.pass, p.gpu_ms);
    ImGui::Text("height %.1f m  speed %.2f m/s  lat %.4f  lon %.4f  sun %.1f deg", g.height,
                controller_->speed(), glm::degrees(g.lat), glm::degrees(g.lon),
                glm::degrees(sun_angles.elevation));
    ImGui::Text("frame %.1f ms  gpu ms:%s", real_dt * 1e3, passes.c_str());
    ImGui::Text("%s  UTC %s%s", body_.name.c_str(), format_utc(clock_.utc()).c_str(),
                recorder_ ? "  [recording]" : "");
    int body_index = 0;
    for (size_t i = 0; i < kBodies.size(); ++i) {
      if (body_key_ == kBodies[i]) body_index = int(i);
    }
    if (ImGui::Combo("body (B)", &body_index, kBodies.data(), int(kBodies.size()))) {
      load(kBodies[size_t(body_index)], false);
    }
    auto names = technique_names();
    if (ImGui::BeginCombo("technique (T)", technique_.c_str())) {
      for (const auto& n : names) {
        if (ImGui::Selectable(n.c_str(), n == technique_)) set_technique(n);
      }
      ImGui::EndCombo();
    }
    // Time of day: moves the clock within the current UTC day.
    double day_start = std::floor((clock_.utc() + 43200.0) / 86400.0) * 86400.0 - 43200.0;
    float hours = float((clock_.utc() - day_start) / 3600.0);
    // Not while recording: the recorded clock must run on without jumps.
    ImGui::BeginDisabled(recorder_ != nullptr || scripted_ != nullptr);
    if (ImGui::SliderFloat("time of day (UTC h)", &hours, 0.0f, 24.0f, "%.2f")) {
      clock_.set(day_start + double(hours) * 3600.0);
    }
    ImGui::EndDisabled();
    int scale_index = 0;
    for (size_t i = 0; i < kTimeScales.size(); ++i) {
      if (clock_.scale() == kTimeScales[i]) scale_index = int(i);
    }
    const char* scale_names[] = {"pause", "x1", "x10", "x100", "x1000", "x10000"};
    if (ImGui::Combo("time scale (P pauses)", &scale_index, scale_names, 6)) {
      clock_.set_scale(kTimeScales[size_t(scale_index)]);
    }
    float log_exposure = float(std::log10(exposure_));
    if (ImGui::SliderFloat("exposure (log10)", &log_exposure, -3.0f, 3.0f, "%.2f")) {
      exposure_ = std::pow(10.0, double(log_exposure));
    }
    if (ImGui::SliderFloat("terrain LOD pixel budget", &lod_pixels_, 0.25f, 8.0f, "%.2f px") &&
        renderer_->terrain()) {
      renderer_->terrain()->set_pixel_budget(double(lod_pixels_));
    }
    ImGui::TextUnformatted("WASD move, R/F up/down, arrows or drag turn, Q/E roll, Shift x10");
    ImGui::TextUnformatted("F12 screenshot, F9 record/stop, Esc quit");
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  FlyArgs args_;
  GLFWwindow* window_;
  SimClock clock_;
  FixedStep step_{kStep};
  double exposure_;
  std::string technique_, body_key_;
  Body body_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::unique_ptr<FlightController> controller_;
  ScriptedFlight* scripted_ = nullptr;  // the controller, when flying a script
  std::unique_ptr<FlightRecorder> recorder_;
  FrameStats stats_;
  GLuint read_fbo_ = 0;
  double mouse_x_ = 0, mouse_y_ = 0;
  long steps_ = 0;
  int screenshots_ = 0, flights_ = 0;
  float lod_pixels_ = 1.0f;
};

void run(const FlyArgs& args) {
  // Fail on bad input before a window opens.
  if (!(args.render_scale > 0.05 && args.render_scale <= 2.0)) {
    throw InputError(fmt::format("--render-scale: {} is not within 0.05 to 2", args.render_scale));
  }
  if (!args.flight_file.empty()) load_flight_script(args.flight_file);
  if (!(args.lat_deg >= -90.0 && args.lat_deg <= 90.0)) {
    throw InputError(fmt::format("--lat: {} is not a latitude (-90 to 90 deg)", args.lat_deg));
  }
  if (!(args.lon_deg >= -180.0 && args.lon_deg <= 360.0)) {
    throw InputError(fmt::format("--lon: {} is not a longitude (-180 to 360 deg)", args.lon_deg));
  }
  if (args.orbit_inclination_deg > 180.0) {
    throw InputError("--orbit-inclination: must be 0 to 180 deg");
  }
  parse_utc(args.time, "--time");
  Body body = load_body(find_body_file(args.planet));
  if (args.height_m < 0) {
    throw InputError(fmt::format("--height: {} m is inside {}", args.height_m, body.name));
  }
  auto names = technique_names();
  if (std::find(names.begin(), names.end(), args.technique) == names.end()) {
    throw InputError(
        fmt::format("--technique: '{}' is not one of {}", args.technique, fmt::join(names, ", ")));
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
  options.title = "planet fly";
  auto context = GlContext::create_window(options);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  // Installed first: ImGui's backend chains to it.
  glfwSetKeyCallback(context->window(), on_key);
  ImGui_ImplGlfw_InitForOpenGL(context->window(), true);
  ImGui_ImplOpenGL3_Init("#version 450");
  {
    FlySession session(args, context->window());
    auto last = std::chrono::steady_clock::now();
    for (;;) {
      auto now = std::chrono::steady_clock::now();
      double dt = std::chrono::duration<double>(now - last).count();
      last = now;
      if (!session.frame(dt)) break;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

}  // namespace

void add_fly_command(CLI::App& app) {
  auto args = std::make_shared<FlyArgs>();
  CLI::App* cmd = app.add_subcommand("fly", "Fly over a body in a window (mouse, keyboard, HUD)");
  cmd->add_option("--planet", args->planet, "Body name or file")->capture_default_str();
  cmd->add_option("--lat", args->lat_deg, "Start latitude, degrees")->capture_default_str();
  cmd->add_option("--lon", args->lon_deg, "Start longitude, degrees")->capture_default_str();
  cmd->add_option("--height", args->height_m, "Start height above the surface, metres")
      ->capture_default_str();
  cmd->add_option("--heading", args->heading_deg, "Start heading, degrees from north")
      ->capture_default_str();
  cmd->add_option("--orbit-inclination", args->orbit_inclination_deg,
                  "Start in a circular orbit at --height with this inclination, degrees");
  cmd->add_option("--time", args->time, "Start time, UTC")->capture_default_str();
  cmd->add_option("--technique", args->technique, "Atmosphere technique")->capture_default_str();
  cmd->add_option("--exposure", args->exposure, "Exposure")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
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
  cmd->add_option("--out", args->out_dir, "Folder for screenshots and recorded flights")
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
}

}  // namespace planet::apps
