#include "render/surface_antialiasing.h"

#include "core/error.h"
#include "gl/context.h"

#include <fmt/format.h>

#include <algorithm>

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
  // As the frame's own surfaces: a frame's pixels that a surface covers
  // whole are the same as at one sample a pixel.
  lit_ = make_texture_2d(GL_RGBA32F, width, height);
  lit_ground_below_ = make_texture_2d(GL_R32F, width, height);
  lit_depth_ = make_texture_2d(GL_DEPTH_COMPONENT32F, width, height);
  lit_fbo_ = make_framebuffer({lit_.id(), lit_ground_below_.id()}, lit_depth_.id());
  // Half floats keep a depth of 2.5 km below the datum to 2 m.
  ground_below_ = make_texture_2d_multisample(GL_R16F, samples, width, height);
  depth_ = make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, samples, width, height);
  coverage_fbo_ = make_framebuffer({ground_below_.id()}, depth_.id());
  // The GL's own sample positions, for the resolve (at most 16: check_samples's
  // callers ask for no more).
  sample_positions_.assign(size_t(2 * std::min(samples, 16)), 0.5f);
  glBindFramebuffer(GL_FRAMEBUFFER, coverage_fbo_.id());
  for (int s = 0; s < std::min(samples, 16); ++s) {
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(s), &sample_positions_[size_t(2 * s)]);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
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
  glBindTextureUnit(0, lit_.id());
  glBindTextureUnit(1, depth_.id());
  glBindTextureUnit(2, ground_below_.id());
  glBindTextureUnit(3, lit_depth_.id());
  glUniform1i(resolve_program_.uniform("u_samples"), samples_);
  glUniform2fv(resolve_program_.uniform("u_sample_positions"), samples_, sample_positions_.data());
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
