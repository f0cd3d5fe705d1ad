#pragma once
// The HUD over the view (Dear ImGui): what the pilot needs to read, and the
// settings the pilot may change. It shows a HudView and returns what the
// pilot changed this frame; the session applies it.
#include <optional>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace planet::apps {

struct HudView {
  double height_m = 0;            // above the ground under the camera
  double height_ellipsoid_m = 0;  // above the body's ellipsoid
  double speed_m_s = 0, lat_deg = 0, lon_deg = 0, sun_elevation_deg = 0;
  double heading_deg = 0, pitch_deg = 0;  // the view's, in the local east-north-up frame
  std::string daylight;                   // "day", "twilight" or "night" (sun_ephemeris.h)
  double frame_ms = 0, gpu_ms = 0;
  std::string passes;  // one line per pass: its GPU ms, or "reused"
  int passes_ran = 0, passes_reused = 0;
  std::string body_name, utc;
  bool recording = false;
  bool clock_locked = false;  // recording or scripted: the clock runs on
  std::vector<std::string> bodies, techniques;
  std::string body, technique;
  double hours_utc = 0;  // within the current UTC day
  double time_scale = 1;
  double exposure = 1;
  float lod_pixels = 1;
  bool terrain_shadows = true;
  bool stars = true;
  bool glare = true;
  bool auto_exposure = false;  // then `exposure` is the frame's measured one
  double error_budget = 0;     // percent; 0: the governor is off
  std::string governor;        // its choice, prediction and the most accurate's cost
  std::string governor_why;    // why, in a line
  // A technique being built between frames (T), then faded in: its name,
  // what it does now and the fraction done; empty when none.
  std::string technique_build, technique_build_step;
  double technique_build_fraction = 0;
};

struct HudChanges {
  std::optional<std::string> body, technique;
  std::optional<double> hours_utc, time_scale, exposure;
  std::optional<float> lod_pixels;
  std::optional<bool> terrain_shadows, stars, auto_exposure, glare;
  std::optional<double> error_budget;  // 0: off
};

class Hud {
 public:
  // After FlyInput: the backend chains to the key callback it finds.
  explicit Hud(GLFWwindow* window);
  ~Hud();
  Hud(const Hud&) = delete;
  Hud& operator=(const Hud&) = delete;

  HudChanges draw(const HudView& view);
  // Whether the HUD has the keyboard or the mouse (a field or a slider
  // being used): the pilot's controls leave them alone.
  bool has_keyboard() const;
  bool has_mouse() const;
  // H: the panel shown or hidden.
  void toggle() { visible_ = !visible_; }
  // The panel's size in the last frame, pixels (0 x 0 hidden).
  std::pair<int, int> size() const { return size_; }

 private:
  bool visible_ = true;
  std::pair<int, int> size_{0, 0};
};

}  // namespace planet::apps
