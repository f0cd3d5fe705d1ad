#include "render/surface_antialiasing.h"

#include "core/error.h"
#include "gl/context.h"

#include <fmt/format.h>

namespace planet {

void SurfaceAntialiasing::check_samples(int samples) {
  GLint most = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &most);
  if (samples < 1 || samples > most) {
    throw SystemError(fmt::format(
        "anti-aliasing: {} samples a pixel asked for; this GL gives 1 to {}", samples, most));
  }
}

SurfaceAntialiasing::SurfaceAntialiasing(int samples, int width, int height)
    : samples_(samples), width_(width), height_(height) {
  check_samples(samples);
  // Half floats: the samples are resolved straight away, and a surface's
  // radiance (at most a few units) keeps 11 bits, far below what the tone
  // map shows. At 1280x720 on llvmpipe (`planet bench
  // --benchmark_filter=TerrainFrame`) the surfaces from 400 km took 90 ms
  // against 125 with RGBA32F (from 2 m, 400 against 391).
  surface_ = make_texture_2d_multisample(GL_RGBA16F, samples, width, height);
  // Half floats keep a depth of 2.5 km below the datum to 2 m.
  ground_below_ = make_texture_2d_multisample(GL_R16F, samples, width, height);
  depth_ = make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, samples, width, height);
  fbo_ = make_framebuffer({surface_.id(), ground_below_.id()}, depth_.id());
  resolve_program_ =
      Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/surface_resolve.frag");
  edges_program_ =
      Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/surface_edges.frag");
  check_gl_errors("SurfaceAntialiasing setup");
}

void SurfaceAntialiasing::resolve(const FullscreenPass& pass, GLuint target) const {
  pass.begin(target, width_, height_, resolve_program_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glBindTextureUnit(0, surface_.id());
  glBindTextureUnit(1, depth_.id());
  glBindTextureUnit(2, ground_below_.id());
  glUniform1i(resolve_program_.uniform("u_samples"), samples_);
  pass.draw();
  glDisable(GL_DEPTH_TEST);
}

void SurfaceAntialiasing::blend_edges(const FullscreenPass& pass, GLuint target, GLuint radiance,
                                      GLuint surface, bool open_is_black) const {
  // The pass reads open pixels and writes only partly covered ones.
  glTextureBarrier();
  pass.begin(target, width_, height_, edges_program_);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glBindTextureUnit(0, radiance);
  glBindTextureUnit(1, surface);
  glUniform1i(edges_program_.uniform("u_open_is_black"), open_is_black ? 1 : 0);
  pass.draw();
  glDisable(GL_BLEND);
}

}  // namespace planet
