#pragma once
// The pilot's keyboard and mouse. Key presses are queued as they arrive: a
// frame on a software renderer can take a second, longer than a tap, so
// polling the key state would miss them. Held keys and a left-button drag
// are read each frame as flight input.
#include "sim/flight_controller.h"

#include <vector>

struct GLFWwindow;

namespace planet::apps {

class FlyInput {
 public:
  // Installs its key callback on the window: before the HUD's backend,
  // which chains to the callback it finds. The window must outlive it.
  explicit FlyInput(GLFWwindow* window);
  ~FlyInput();
  FlyInput(const FlyInput&) = delete;
  FlyInput& operator=(const FlyInput&) = delete;

  // Keys pressed since the last call, in order; dropped while the HUD has
  // the keyboard (typing into a field is not flying).
  std::vector<int> take_presses(bool hud_has_keyboard);
  // Held keys (WASD, R/F, arrows, Q/E, Shift) and the mouse drag; nothing
  // from the devices the HUD has.
  FlightInput read(bool hud_has_keyboard, bool hud_has_mouse);

 private:
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);

  GLFWwindow* window_;
  std::vector<int> presses_;
  double mouse_x_ = 0, mouse_y_ = 0;
};

}  // namespace planet::apps
