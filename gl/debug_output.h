#pragma once
// What a debug context's driver says of the GL calls (KHR_debug). An error,
// or a message of high severity, is kept for the next check_gl_errors()
// (gl/context.h) and, where a handler is set, handed to it at once, on the
// thread that made the call: the test programs set one that fails the
// test running, so a GL error fails the test whose call made it even where
// the code never checks. Each report names the call, as the driver does
// ("GL_INVALID_OPERATION in glBindTexture(non-gen name)"), and the debug
// groups open around it ("in pass sky_view_lut": GpuTimer opens one for
// each pass it times).
#include <string>

namespace planet {

using GlErrorHandler = void (*)(const std::string& report);
// nullptr: none (the program's default).
void set_gl_error_handler(GlErrorHandler handler);

}  // namespace planet
