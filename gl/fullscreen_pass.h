#pragma once
// A pass that writes every pixel of a target: one triangle over the
// viewport (gl/shaders/fullscreen.vert, which gives the fragment shader its
// pixel's NDC as v_ndc), with no depth test and no blending.
#include "gl/program.h"
#include "gl/texture.h"

namespace planet {

class FullscreenPass {
 public:
  // Needs a current GL context.
  FullscreenPass();

  // Binds the target and its viewport and uses the program; set its
  // uniforms and textures, then draw().
  void begin(GLuint framebuffer, int width, int height, const Program& program) const;
  void draw() const;
  // Draws what the buffer bound to GL_DRAW_INDIRECT_BUFFER says (a
  // DrawArraysIndirectCommand at its start) with no vertex attributes:
  // for a vertex shader that places its own triangles, in place of the
  // one over the viewport.
  void draw_indirect() const;

 private:
  VertexArray empty_vao_;
};

}  // namespace planet
