#include "gl/schedule.h"

#include "core/error.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

namespace planet {

namespace {

std::optional<Schedule>& asked() {
  static std::optional<Schedule> schedule;
  return schedule;
}

}  // namespace

std::string schedule_name(Schedule schedule) {
  return schedule == Schedule::kSoftware ? "software" : "plain";
}

Schedule schedule_for_renderer(std::string_view renderer) {
  for (std::string_view software : {"llvmpipe", "softpipe", "SwiftShader"}) {
    if (renderer.find(software) != std::string_view::npos) return Schedule::kSoftware;
  }
  return Schedule::kPlain;
}

std::optional<Schedule> parse_schedule(std::string_view text, std::string_view option) {
  if (text == "software") return Schedule::kSoftware;
  if (text == "plain") return Schedule::kPlain;
  if (text == "auto") return std::nullopt;
  throw InputError(
      fmt::format("{}: \"{}\" is not a schedule (software, plain or auto)", option, text));
}

void set_schedule(std::optional<Schedule> schedule) { asked() = schedule; }

Schedule current_schedule() {
  if (asked()) return *asked();
  const GLubyte* renderer = glGetString(GL_RENDERER);
  return schedule_for_renderer(renderer ? reinterpret_cast<const char*>(renderer) : "");
}

}  // namespace planet
