#pragma once
// Anti-aliasing of the surfaces' edges, with their light computed once a
// pixel: the surfaces drawn lit at one sample a pixel, and again
// multisampled without light (their coverage and depth per sample), then
// resolved to one surface per pixel with its coverage
// (shaders/surface_resolve.frag), so that the atmosphere shades each pixel
// once; after it, a partly covered pixel takes the rest from the open sky
// beside it (shaders/surface_edges.frag). A GL that shades each sample of
// a multisampled pixel (llvmpipe) so runs the surfaces' light once a
// pixel, not once a sample.
#include "gl/fullscreen_pass.h"
#include "gl/program.h"
#include "gl/texture.h"

#include <vector>

namespace planet {

class SurfaceAntialiasing {
 public:
  // Needs a current GL 4.5 context. `samples` a pixel, 2 or more;
  // SystemError for a count the GL cannot give.
  SurfaceAntialiasing(int samples, int width, int height);
  // SystemError unless the GL gives `samples` a pixel (1: none, always).
  static void check_samples(int samples);

  // The lit surfaces' target, one sample a pixel: colour, the ground below
  // the datum, depth (as the frame's own surfaces' target).
  GLuint framebuffer() const { return lit_fbo_.id(); }
  // The multisampled coverage's target: the ground below the datum, depth
  // (TerrainRenderer::draw's `coverage`).
  GLuint coverage_framebuffer() const { return coverage_fbo_.id(); }
  // The two to one surface per pixel in `target` (colour, the ground below
  // the datum, depth), its depth written whatever it is.
  void resolve(const FullscreenPass& pass, GLuint target) const;
  // The partly covered pixels of `target` (holding `radiance`) take the
  // rest from the open ones beside them; `open_is_black`: the open pixels
  // hold no sky (an airless body).
  void blend_edges(const FullscreenPass& pass, GLuint target, GLuint radiance, GLuint surface,
                   bool open_is_black) const;

 private:
  int samples_, width_, height_;
  // One sample a pixel; the ground below the datum is terrain.frag's
  // second target, the resolve takes the farthest sample's.
  Texture lit_, lit_ground_below_, lit_depth_;
  Texture ground_below_, depth_;  // multisampled
  Framebuffer lit_fbo_, coverage_fbo_;
  Program resolve_program_, edges_program_;
  std::vector<float> sample_positions_;  // x, y of each sample in its pixel
};

}  // namespace planet
