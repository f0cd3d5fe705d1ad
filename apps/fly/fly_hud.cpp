#include "apps/fly/fly_hud.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>

#include <array>
#include <cmath>

namespace planet::apps {

namespace {

const std::array<double, 6> kTimeScales = {0.0, 1.0, 10.0, 100.0, 1000.0, 10000.0};
const char* kTimeScaleNames[] = {"pause", "x1", "x10", "x100", "x1000", "x10000"};
// Settings take this much width: the panel stays a corner of the view.
constexpr float kItemWidth = 150.0f;
// A technique being built shows its progress in this much beside the clock.
constexpr float kBuildBarWidth = 100.0f;

// Metres per second near the ground, km/s higher up (free flight's speed
// runs from a walk to thousands of km/s).
std::string speed_text(double m_s) {
  return m_s < 1e3 ? fmt::format("{:.1f} m/s", m_s) : fmt::format("{:.1f} km/s", m_s / 1e3);
}

// Three lines, as narrow as they go: the panel stays a corner of the view.
void draw_status(const HudView& v) {
  // While a technique is built its progress sits beside the clock, which
  // gives up its date for it, so that the panel grows no larger.
  const bool building = !v.technique_build.empty();
  const std::size_t t = v.utc.find('T');
  const std::string clock = building && t != std::string::npos ? v.utc.substr(t + 1) : v.utc;
  ImGui::Text("%s  %s  sun %.1f deg %s", v.body_name.c_str(), clock.c_str(), v.sun_elevation_deg,
              v.daylight.c_str());
  if (building) {
    ImGui::SameLine();
    const std::string bar = fmt::format("{} {:.0f} %", v.technique_build,
                                        std::floor(100.0 * v.technique_build_fraction));
    ImGui::ProgressBar(float(v.technique_build_fraction), ImVec2(kBuildBarWidth, 0.0f),
                       bar.c_str());
    // What the build does now, under the pointer.
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", v.technique_build_step.c_str());
  }
  ImGui::Text("%.1f m above ground (%.0f m ellipsoid)  speed %s", v.height_m, v.height_ellipsoid_m,
              speed_text(v.speed_m_s).c_str());
  ImGui::Text("lat %.4f lon %.4f  heading %.1f pitch %.1f", v.lat_deg, v.lon_deg, v.heading_deg,
              v.pitch_deg);
}

void draw_frame_line(const HudView& v) {
  // The frame's rate and cost, and how many of its passes reused an
  // earlier frame's result; unfolded, each pass's GPU time or "reused".
  const std::string frame_line =
      fmt::format("{:.1f} fps  gpu {:.0f} ms  {}  {}/{} reused###passes",
                  v.frame_ms > 0 ? 1e3 / v.frame_ms : 0.0, v.gpu_ms, v.technique, v.passes_reused,
                  v.passes_ran + v.passes_reused);
  if (ImGui::CollapsingHeader(frame_line.c_str())) {
    if (!v.governor.empty()) {
      ImGui::TextUnformatted(v.governor.c_str());
      ImGui::TextWrapped("%s", v.governor_why.c_str());
    }
    ImGui::TextUnformatted(v.passes.c_str());
  }
}

void draw_settings(const HudView& v, HudChanges& changes) {
  if (!ImGui::CollapsingHeader("settings")) return;
  ImGui::PushItemWidth(kItemWidth);
  if (ImGui::BeginCombo("body (B)", v.body.c_str())) {
    for (const auto& b : v.bodies) {
      if (ImGui::Selectable(b.c_str(), b == v.body)) changes.body = b;
    }
    ImGui::EndCombo();
  }
  if (ImGui::BeginCombo("sky (T)", v.technique.c_str())) {
    for (const auto& t : v.techniques) {
      if (ImGui::Selectable(t.c_str(), t == v.technique)) changes.technique = t;
    }
    ImGui::EndCombo();
  }
  // Not while recording or flying a script: the clock must run on
  // without jumps.
  ImGui::BeginDisabled(v.clock_locked);
  float hours = float(v.hours_utc);
  if (ImGui::SliderFloat("UTC hour", &hours, 0.0f, 24.0f, "%.2f")) {
    changes.hours_utc = double(hours);
  }
  ImGui::EndDisabled();
  int scale_index = 0;
  for (size_t i = 0; i < kTimeScales.size(); ++i) {
    if (v.time_scale == kTimeScales[i]) scale_index = int(i);
  }
  if (ImGui::Combo("clock (P)", &scale_index, kTimeScaleNames, int(kTimeScales.size()))) {
    changes.time_scale = kTimeScales[size_t(scale_index)];
  }
  float log_exposure = float(std::log10(v.exposure));
  if (ImGui::SliderFloat("log exposure", &log_exposure, -3.0f, 4.0f,
                         v.auto_exposure ? "%.2f (auto)" : "%.2f")) {
    changes.exposure = std::pow(10.0, double(log_exposure));
    changes.auto_exposure = false;  // a hand on the slider takes over
  }
  bool automatic = v.auto_exposure;
  if (ImGui::Checkbox("auto exposure", &automatic)) changes.auto_exposure = automatic;
  // The governor: off at 0, else the error it may spend, percent.
  float budget = float(v.error_budget);
  if (ImGui::SliderFloat("error budget", &budget, 0.0f, 50.0f,
                         budget > 0 ? "%.1f %%" : "off (technique)",
                         ImGuiSliderFlags_Logarithmic)) {
    changes.error_budget = double(budget < 0.1f ? 0.0f : budget);
  }
  float lod = v.lod_pixels;
  if (ImGui::SliderFloat("LOD error", &lod, 0.25f, 8.0f, "%.2f px")) changes.lod_pixels = lod;
  bool shadows = v.terrain_shadows;
  if (ImGui::Checkbox("terrain shadows", &shadows)) changes.terrain_shadows = shadows;
  bool stars = v.stars;
  if (ImGui::Checkbox("stars", &stars)) changes.stars = stars;
  bool glare = v.glare;
  if (ImGui::Checkbox("glare", &glare)) changes.glare = glare;
  ImGui::PopItemWidth();
}

void draw_keys() {
  if (ImGui::CollapsingHeader("keys")) {
    ImGui::TextUnformatted("WASD move, R/F up/down, Shift x10");
    ImGui::TextUnformatted("arrows or drag turn, Q/E roll");
    ImGui::TextUnformatted("B body, T sky, P clock, H HUD");
    ImGui::TextUnformatted("F12 screenshot, F9 record, Esc quit");
  }
}

}  // namespace

Hud::Hud(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

Hud::~Hud() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

bool Hud::has_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }
bool Hud::has_mouse() const { return ImGui::GetIO().WantCaptureMouse; }

HudChanges Hud::draw(const HudView& v) {
  HudChanges changes;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (!visible_) {
    size_ = {0, 0};
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return changes;
  }
  // A compact panel in the corner, sized to what it shows; its title bar
  // folds it away, H hides it.
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.6f);
  // A recording says so in the title (one id for both titles: the panel
  // keeps its place and folding).
  ImGui::Begin(v.recording ? "planet [rec] (H hides)###planet" : "planet (H hides)###planet",
               nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  draw_status(v);
  draw_frame_line(v);
  draw_settings(v, changes);
  draw_keys();
  ImVec2 size = ImGui::GetWindowSize();
  size_ = {int(size.x), int(size.y)};
  ImGui::End();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return changes;
}

}  // namespace planet::apps
