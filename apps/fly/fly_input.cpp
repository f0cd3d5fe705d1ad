#include "apps/fly/fly_input.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace planet::apps {

FlyInput::FlyInput(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, on_key);
  glfwGetCursorPos(window, &mouse_x_, &mouse_y_);
}

FlyInput::~FlyInput() {
  glfwSetKeyCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

void FlyInput::on_key(GLFWwindow* window, int key, int, int action, int) {
  auto* self = static_cast<FlyInput*>(glfwGetWindowUserPointer(window));
  if (self && action == GLFW_PRESS) self->presses_.push_back(key);
}

std::vector<int> FlyInput::take_presses(bool hud_has_keyboard) {
  std::vector<int> keys;
  keys.swap(presses_);
  if (hud_has_keyboard) keys.clear();
  return keys;
}

FlightInput FlyInput::read(bool hud_has_keyboard, bool hud_has_mouse) {
  FlightInput in;
  double x, y;
  glfwGetCursorPos(window_, &x, &y);
  if (!hud_has_keyboard) {
    auto key = [&](int k) { return glfwGetKey(window_, k) == GLFW_PRESS ? 1.0 : 0.0; };
    in.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_R) - key(GLFW_KEY_F),
               key(GLFW_KEY_W) - key(GLFW_KEY_S)};
    in.turn = {key(GLFW_KEY_UP) - key(GLFW_KEY_DOWN), key(GLFW_KEY_LEFT) - key(GLFW_KEY_RIGHT),
               key(GLFW_KEY_E) - key(GLFW_KEY_Q)};
    in.boost = key(GLFW_KEY_LEFT_SHIFT) > 0 ? 10.0 : 1.0;
  }
  // Drag with the left button to look around.
  if (!hud_has_mouse && glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
    in.turn.y += std::clamp(-(x - mouse_x_) * 0.2, -1.0, 1.0);
    in.turn.x += std::clamp(-(y - mouse_y_) * 0.2, -1.0, 1.0);
  }
  mouse_x_ = x;
  mouse_y_ = y;
  return in;
}

}  // namespace planet::apps
