#pragma once
// Anti-aliasing of the surfaces' edges: the surfaces drawn multisampled,
// then resolved to one surface per pixel with its coverage
// (shaders/surface_resolve.frag), so that the atmosphere shades each pixel
// once; after it, a partly covered pixel takes the rest from the open sky
// beside it (shaders/surface_edges.frag).
#include "gl/fullscreen_pass.h"
#include "gl/program.h"
#include "gl/texture.h"

namespace planet {

class SurfaceAntialiasing {
 public:
  // Needs a current GL 4.5 context. `samples` a pixel, 2 or more;
  // SystemError for a count the GL cannot give.
  SurfaceAntialiasing(int samples, int width, int height);
  // SystemError unless the GL gives `samples` a pixel (1: none, always).
  static void check_samples(int samples);

  // The multisampled surfaces' target: colour, the ground below the datum,
  // depth.
  GLuint framebuffer() const { return fbo_.id(); }
  // The samples to one surface per pixel in `target` (colour, the ground
  // below the datum, depth), its depth written whatever it is.
  void resolve(const FullscreenPass& pass, GLuint target) const;
  // The partly covered pixels of `target` (holding `radiance`) take the
  // rest from the open ones beside them; `open_is_black`: the open pixels
  // hold no sky (an airless body).
  void blend_edges(const FullscreenPass& pass, GLuint target, GLuint radiance, GLuint surface,
                   bool open_is_black) const;

 private:
  int samples_, width_, height_;
  Texture surface_, ground_below_, depth_;
  Framebuffer fbo_;
  Program resolve_program_, edges_program_;
};

}  // namespace planet
