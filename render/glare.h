#pragma once
// Glare: the light the eye scatters around a bright source, as the CIE
// disability glare equation gives it (Vos 2003, after Stiles and Holladay):
// a veil of 10 E / theta^2 (theta in degrees) per steradian for an
// illuminance E, which puts the same share of the light into each octave of
// theta. The frame's radiance is halved again and again into a pyramid, one
// level per octave, and summed back up; the tone map
// (render/shaders/tonemap.frag) takes each octave's share from the pixel
// and adds the sum.
#include "gl/fullscreen_pass.h"
#include "gl/program.h"
#include "gl/texture.h"

#include <cmath>
#include <vector>

namespace planet {

// The share of the light in each octave of angle:
// 10 x 2 pi ln 2 / (180 / pi)^2 = 1.33 %.
constexpr double kGlarePerOctave = 10.0 * 2.0 * M_PI * M_LN2 / ((180.0 / M_PI) * (180.0 / M_PI));

class GlarePyramid {
 public:
  // Needs a current GL 4.5 context: half the frame's size and down by
  // halves, at most six octaves.
  GlarePyramid(int width, int height);
  // The pyramid of `radiance` (the frame's, width x height), drawn with
  // `pass`; sum() then holds the glare's light.
  void draw(const FullscreenPass& pass, GLuint radiance);
  GLuint sum() const { return up_[0].id(); }
  int octaves() const { return int(up_.size()); }

 private:
  std::vector<Texture> down_, up_;
  std::vector<Framebuffer> down_fbo_, up_fbo_;
  Program down_program_, up_program_;
};

}  // namespace planet
