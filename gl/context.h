#pragma once
// An OpenGL 4.5 core context: EGL surfaceless for headless work (capture,
// tests, benchmarks), or a GLFW window for flying. Rendering always goes
// into framebuffer objects; the window only receives the final blit.
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace planet {

struct ContextOptions {
  // GL debug output: errors reported by the driver become exceptions at the
  // next check_gl_errors(), and test failures in the test programs
  // (gl/debug_output.h). On in debug builds and tests; elsewhere set
  // PLANET_GL_DEBUG=1 to turn it on.
  bool debug = default_debug();
  static bool default_debug();
  // Window only.
  int width = 1280, height = 720;
  std::string title = "planet";
  bool visible = true;
};

class GlContext {
 public:
  // Headless: EGL on Mesa's surfaceless platform. Throws SystemError with
  // what to install when no EGL display or no 4.5 core context can be had.
  static std::unique_ptr<GlContext> create_headless(const ContextOptions& options = {});
  // A GLFW window with a 4.5 core context, current on this thread.
  static std::unique_ptr<GlContext> create_window(const ContextOptions& options);

  virtual ~GlContext() = default;
  virtual GLFWwindow* window() const { return nullptr; }
  // "4.5 (Core Profile) Mesa 22.3.6" and "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string version() const;
  std::string renderer() const;

 protected:
  GlContext() = default;
  void check_version_and_enable_debug(bool debug);
};

// Throws SystemError listing any GL errors reported since the last call
// (debug output messages of error type, and glGetError), with `where`.
void check_gl_errors(const char* where);

}  // namespace planet
