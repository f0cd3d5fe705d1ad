#include "render/glare.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

constexpr int kGlareOctaves = 6;

glm::ivec2 texture_size(const Texture& t) {
  GLint w = 0, h = 0;
  glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_WIDTH, &w);
  glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_HEIGHT, &h);
  return {w, h};
}

}  // namespace

GlarePyramid::GlarePyramid(int width, int height)
    : down_program_(
          Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/glare_down.frag")),
      up_program_(Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/glare_up.frag")) {
  int w = width, h = height;
  for (int level = 0; level < kGlareOctaves && (w > 1 || h > 1); ++level) {
    w = std::max(1, (w + 1) / 2);
    h = std::max(1, (h + 1) / 2);
    down_.push_back(make_texture_2d(GL_RGBA16F, w, h));
    up_.push_back(make_texture_2d(GL_RGBA16F, w, h));
    down_fbo_.push_back(make_framebuffer(down_.back().id(), 0));
    up_fbo_.push_back(make_framebuffer(up_.back().id(), 0));
  }
}

// Each level keeps the image's energy on the way down; on the way up each
// coarser level is spread one octave wider. Equal shares per octave make
// the 1 / theta^2 of the glare equation.
void GlarePyramid::draw(const FullscreenPass& pass, GLuint radiance) {
  const size_t levels = down_.size();
  for (size_t i = 0; i < levels; ++i) {
    glm::ivec2 s = texture_size(down_[i]);
    pass.begin(down_fbo_[i].id(), s.x, s.y, down_program_);
    glBindTextureUnit(0, i == 0 ? radiance : down_[i - 1].id());
    pass.draw();
  }
  // The coarsest level is its own sum.
  glm::ivec2 last = texture_size(down_[levels - 1]);
  glCopyImageSubData(down_[levels - 1].id(), GL_TEXTURE_2D, 0, 0, 0, 0, up_[levels - 1].id(),
                     GL_TEXTURE_2D, 0, 0, 0, 0, last.x, last.y, 1);
  for (size_t i = levels - 1; i-- > 0;) {
    glm::ivec2 s = texture_size(up_[i]);
    pass.begin(up_fbo_[i].id(), s.x, s.y, up_program_);
    glBindTextureUnit(0, down_[i].id());
    glBindTextureUnit(1, up_[i + 1].id());
    pass.draw();
  }
}

}  // namespace planet
