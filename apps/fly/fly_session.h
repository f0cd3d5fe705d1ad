#pragma once
// One flight in a window: the body and its atmosphere technique, the
// pilot's controller (free flight, an orbit or a script), the simulation
// clock in fixed steps, the renderer, recording and screenshots.
#include "apps/fly/fly_hud.h"
#include "apps/fly/fly_input.h"
#include "gl/pass_tally.h"
#include "gl/texture.h"
#include "governor/governor.h"
#include "render/frame.h"
#include "render/technique_handover.h"
#include "render/technique_switch.h"
#include "sim/body.h"
#include "sim/flight_controller.h"
#include "sim/flight_recorder.h"
#include "sim/geodesy.h"
#include "sim/scripted_flight.h"
#include "sim/utc_time.h"

#include <cmath>
#include <memory>
#include <optional>
#include <string>

struct GLFWwindow;

namespace planet::apps {

// The window's title (the tests find the window by it); a long wait puts
// its progress after it.
inline constexpr const char* kFlyTitle = "planet fly";

struct FlyArgs {
  std::string planet = "earth", technique = "hillaire", time = "2026-06-21T10:00:00Z";
  // height_m counts from the ground under the start place.
  double lat_deg = 46.55, lon_deg = 7.98, height_m = 2.0, heading_deg = 90.0;
  double orbit_inclination_deg = -1;
  int width = 960, height = 540;
  double render_scale = 0.5;  // of the window; llvmpipe is slow at full size
  // Samples a pixel for the surfaces' edges; 1: none; 0: a capture's
  // default (4), or on llvmpipe the image's edges smoothed instead (FXAA).
  int antialiasing = 0;
  double exposure = 8.0, vertical_fov_deg = 60.0;
  bool auto_exposure = false;  // each frame's own, from its mean luminance
  // --pass-table: each pass's wall time kept (a synchronous timer) and the
  // table of passes printed at the end (PassTally::table).
  bool pass_table = false;
  bool exposure_given = false;  // --exposure on the command line: kept at night too
  std::string out_dir = ".";
  std::string flight_file;  // fly a script instead of the start place
  bool technique_given = false;  // --technique on the command line: it wins over a budget
  double error_budget = std::nan("");  // --error-budget, percent; NaN: none given
  std::string error_model;       // the governor's table; empty: the shipped one
};

class FlySession {
 public:
  FlySession(const FlyArgs& args, GLFWwindow* window, FlyInput& input, Hud& hud);

  // One frame of the program: input, fixed steps, render, HUD. False to quit.
  bool frame(double real_dt);
  // Every frame's passes so far.
  const PassTally& passes() const { return tally_; }

 private:
  Camera camera() const;
  // The ground's height above the ellipsoid under a place, for this body.
  double ground_at(const Geodetic& place) const;
  glm::dvec3 sun_dir() const;
  void attach(const Body& body);
  void load(const std::string& name, bool from_args);
  // "sun E deg: day" (twilight, night) at a place of the body; not by day,
  // the exposure turns automatic unless the command line fixed it.
  std::string light_up(const Geodetic& place);
  void set_technique(const std::string& name);
  // The technique being built between frames, then faded in (T).
  void advance_handover(double real_dt);
  // A budget (percent) lets the governor choose; 0 turns it off.
  void set_error_budget(double percent);
  void handle_key(int key);
  void apply(const HudChanges& changes);
  HudView hud_view(const Camera& cam, const glm::dvec3& sun, double real_dt) const;
  void blit();
  void screenshot();
  void toggle_recording();

  FlyArgs args_;
  GLFWwindow* window_;
  FlyInput& input_;
  Hud& hud_;
  SimClock clock_;
  FixedStep step_;
  double exposure_;
  std::string technique_, body_key_;
  Body body_;
  std::optional<AtmosphereModel> atmosphere_;  // of body_
  ErrorModel error_model_;
  double error_budget_ = 0;  // percent; 0: the governor is off
  std::optional<Governor> governor_;
  std::optional<TechniqueSwitch> switch_;
  std::optional<GovernorDecision> decision_;
  std::unique_ptr<Geodesy> geodesy_;  // of body_
  std::unique_ptr<FrameRenderer> renderer_;
  Framebuffer ldr_framebuffer_;  // the renderer's tone-mapped target, to blit from
  std::unique_ptr<TechniqueHandover> handover_;  // after renderer_: it ends the renderer's fade
  double draw_seconds_ = 0;  // the last frame's own time, without a handover's build
  std::unique_ptr<FlightController> controller_;
  ScriptedFlight* scripted_ = nullptr;  // the controller, when flying a script
  std::unique_ptr<FlightRecorder> recorder_;
  FrameStats stats_;
  PassTally tally_;
  long steps_ = 0;
  int screenshots_ = 0, flights_ = 0;
  float lod_pixels_ = 1.0f;
};

}  // namespace planet::apps
