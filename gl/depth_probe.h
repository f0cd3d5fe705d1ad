#pragma once
// Whether any pixel of a reversed-Z depth texture holds a surface nearer
// than a given view depth: one full-screen pass that tests depth and writes
// nothing, counted by an occlusion query. Waits for the GL to have drawn
// the surfaces; on a software rasteriser that costs a depth test per pixel,
// far less than a pass it lets a frame leave out.
#include "gl/fullscreen_pass.h"
#include "gl/program.h"
#include "gl/texture.h"

namespace planet {

class DepthProbe {
 public:
  // Needs a current GL context.
  DepthProbe();
  ~DepthProbe();
  DepthProbe(const DepthProbe&) = delete;
  DepthProbe& operator=(const DepthProbe&) = delete;

  // True when some pixel of `depth_texture` (width x height, reversed Z:
  // depth = near / view depth, 0 where nothing was drawn) lies at a view
  // depth of at most `view_depth`.
  bool any_nearer(GLuint depth_texture, int width, int height, float near, float view_depth);

 private:
  Program program_;
  FullscreenPass pass_;
  Framebuffer framebuffer_;
  GLuint attached_ = 0;  // the depth texture framebuffer_ holds
  GLuint query_ = 0;
};

}  // namespace planet
