#pragma once
// How a technique schedules its passes for the rasteriser it runs on. A
// software rasteriser (Mesa's llvmpipe and softpipe, SwiftShader) runs
// every side of a fragment shader's branches over a block of pixels, so
// the techniques split their passes there: stencil classes that hold each
// program to the pixels it serves, variants compiled without the code a
// frame does not take, tiles listed on the GPU for the costly part. A GPU
// pays for those splits (more draws, a classifying pass, the stencil) and
// gains little: it takes the plain path, one program for every pixel.
// Both draw the same image within a stated tolerance
// (ScheduleGLTest.BothSchedulesDrawTheSameSky).
#include <optional>
#include <string>
#include <string_view>

namespace planet {

enum class Schedule { kSoftware, kPlain };

// "software" or "plain".
std::string schedule_name(Schedule schedule);
// The schedule for a GL_RENDERER string: software for llvmpipe, softpipe
// and SwiftShader, plain for anything else.
Schedule schedule_for_renderer(std::string_view renderer);
// "software", "plain" or "auto" (nullopt: by the renderer); InputError
// naming `option` and the value otherwise.
std::optional<Schedule> parse_schedule(std::string_view text, std::string_view option);

// The schedule that techniques built from now on take: the one a command
// asked for (`--schedule`), or by the current GL context's renderer when it
// asked for none or for auto. Needs a current GL context when auto.
void set_schedule(std::optional<Schedule> schedule);
Schedule current_schedule();

}  // namespace planet
