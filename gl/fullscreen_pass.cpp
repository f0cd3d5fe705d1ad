#include "gl/fullscreen_pass.h"

namespace planet {

FullscreenPass::FullscreenPass() {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  empty_vao_ = VertexArray(vao);
}

void FullscreenPass::begin(GLuint framebuffer, int width, int height,
                           const Program& program) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  program.use();
}

void FullscreenPass::draw() const {
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void FullscreenPass::draw_indirect() const {
  glBindVertexArray(empty_vao_.id());
  glDrawArraysIndirect(GL_TRIANGLES, nullptr);
}

}  // namespace planet
