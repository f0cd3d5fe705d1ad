#include "gl/context.h"

#include "core/error.h"
#include "gl/debug_output.h"
#include "gl/driver_watch.h"

// epoxy before GLFW: GLFW would pull in the Khronos GL header first.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <atomic>
#include <cstdlib>
#include <mutex>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace planet {

namespace {

const char* kInstallHint =
    "install Mesa's EGL and GL drivers (Debian: libegl-mesa0 libgl1-mesa-dri) "
    "or run on a machine with an OpenGL 4.5 driver";

std::mutex g_errors_mutex;
std::vector<std::string> g_errors;
std::atomic<GlErrorHandler> g_error_handler{nullptr};
// The debug groups open on this thread, outermost first, as the driver's
// own messages on each push and pop tell them (debug output is synchronous:
// its messages come on the thread of the call).
thread_local std::vector<std::string> t_groups;

void GLAPIENTRY on_debug_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                 const GLchar* message, const void*) {
  if (type == GL_DEBUG_TYPE_PUSH_GROUP) {
    t_groups.emplace_back(message);
    return;
  }
  if (type == GL_DEBUG_TYPE_POP_GROUP) {
    if (!t_groups.empty()) t_groups.pop_back();
    return;
  }
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  std::string report = message;
  if (!t_groups.empty()) report += fmt::format(" in pass {}", fmt::join(t_groups, " / "));
  if (GlErrorHandler handler = g_error_handler.load()) handler(report);
  std::lock_guard lock(g_errors_mutex);
  if (g_errors.size() < 16) g_errors.push_back(std::move(report));
}

// While it lives, this thread flushes denormal floats to zero, as GPUs do
// for 32-bit floats and GLSL allows: the threads that a software driver
// (llvmpipe) starts meanwhile, which run the shaders, take this mode from
// it; this thread's own is restored after. llvmpipe's shader threads
// otherwise keep denormals, which the x86 handles in microcode a hundred
// times slower: in air so thick or a night so deep that the light falls
// below 1.2e-38, hillaire's third order of scattering took 41 ms where
// the fourth, the same work, took 20.
class DenormalsFlushedForDriverThreads {
 public:
  DenormalsFlushedForDriverThreads() {
#if defined(__SSE__)
    saved_ = _mm_getcsr();
    _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
#endif
  }
  ~DenormalsFlushedForDriverThreads() {
#if defined(__SSE__)
    _mm_setcsr(saved_);
#endif
  }
  DenormalsFlushedForDriverThreads(const DenormalsFlushedForDriverThreads&) = delete;
  DenormalsFlushedForDriverThreads& operator=(const DenormalsFlushedForDriverThreads&) = delete;

 private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_ = 0;
};

class EglContext final : public GlContext {
 public:
  explicit EglContext(const ContextOptions& options) {
    DenormalsFlushedForDriverThreads denormals;
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
      throw SystemError(
          fmt::format("EGL: no surfaceless platform (EGL_MESA_platform_surfaceless) for headless "
                      "rendering; {}",
                      kInstallHint));
    }
    display_ =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      throw SystemError(fmt::format("EGL: cannot open a surfaceless display; {}", kInstallHint));
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      throw SystemError(fmt::format("EGL: the display has no desktop OpenGL; {}", kInstallHint));
    }
    EGLint flags = options.debug ? EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR : 0;
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_FLAGS_KHR,
                                 flags,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
      eglTerminate(display_);
      throw SystemError(fmt::format("EGL: the driver cannot create an OpenGL 4.5 core context; {}",
                                    kInstallHint));
    }
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      eglDestroyContext(display_, context_);
      eglTerminate(display_);
      throw SystemError("EGL: cannot make the context current without a surface");
    }
    check_version_and_enable_debug(options.debug);
  }

  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // The display is shared by every context on it; terminating it would
    // break a second context in the same process.
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

class GlfwContext final : public GlContext {
 public:
  explicit GlfwContext(const ContextOptions& options) {
    DenormalsFlushedForDriverThreads denormals;
    if (!glfwInit()) {
      throw SystemError("GLFW: cannot initialise (no display? set DISPLAY, or use capture)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    window_ =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw SystemError(
          fmt::format("GLFW: cannot open a window with OpenGL 4.5 core; {}", kInstallHint));
    }
    glfwMakeContextCurrent(window_);
    check_version_and_enable_debug(options.debug);
  }
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GLFWwindow* window() const override { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

bool ContextOptions::default_debug() {
#ifdef NDEBUG
  const char* env = std::getenv("PLANET_GL_DEBUG");
  return env && std::string(env) == "1";
#else
  return true;
#endif
}

std::unique_ptr<GlContext> GlContext::create_headless(const ContextOptions& options) {
  driver_timeout_seconds();  // a bad PLANET_GL_TIMEOUT_S is said before any work
  return std::make_unique<EglContext>(options);
}

std::unique_ptr<GlContext> GlContext::create_window(const ContextOptions& options) {
  driver_timeout_seconds();
  return std::make_unique<GlfwContext>(options);
}

std::string GlContext::version() const {
  return reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

std::string GlContext::renderer() const {
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

void GlContext::check_version_and_enable_debug(bool debug) {
  int version = epoxy_gl_version();
  if (version < 45) {
    throw SystemError(fmt::format("OpenGL {}.{} found, 4.5 core needed ({}); {}", version / 10,
                                  version % 10, renderer(), kInstallHint));
  }
  t_groups.clear();  // a new context has no group open
  if (debug) {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(on_debug_message, nullptr);
    // The groups' own messages name the pass of an error that follows.
    for (GLenum type : {GL_DEBUG_TYPE_PUSH_GROUP, GL_DEBUG_TYPE_POP_GROUP}) {
      glDebugMessageControl(GL_DONT_CARE, type, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    }
  }
  // Reversed-Z: depth 1 at the near plane, 0 at infinity.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
}

void set_gl_error_handler(GlErrorHandler handler) { g_error_handler = handler; }

void check_gl_errors(const char* where) {
  std::vector<std::string> errors;
  {
    std::lock_guard lock(g_errors_mutex);
    errors.swap(g_errors);
  }
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    errors.push_back(fmt::format("glGetError 0x{:x}", e));
  }
  if (!errors.empty()) {
    throw SystemError(fmt::format("GL error in {}: {}", where, fmt::join(errors, "; ")));
  }
}

}  // namespace planet
