#pragma once
// The frame's cloud pass (clouds.frag): the body's cloud layer marched over
// the radiance the atmosphere's technique drew, lit by the sun through the
// air and by the sky's light, with the air in front of the clouds.
#include "atmosphere/gpu/technique.h"
#include "clouds/math/cloud_math.h"
#include "gl/fullscreen_pass.h"
#include "gl/program.h"

#include <array>

namespace planet {

// The march's cost and accuracy: what the lab varies.
struct CloudQuality {
  int steps = 32;       // samples along a view ray in the layer
  int light_steps = 4;  // samples toward the sun from each
  // Wrenninge's octaves of multiple scattering (1: single): each costs an
  // exp() a sample; below 6 the inside of a thick cloud and its base
  // from below go nearly black.
  int octaves = 6;
  // The march at one pixel in each block of downsample x downsample, the
  // rest blended from the marched ones that see the same surface
  // (clouds_upsample.frag): 1 marches every pixel.
  int downsample = 2;
};

// CloudLayer's twelve fields in their order, as the shaders' vec4
// u_layer[3] takes them (clouds.frag).
std::array<float, 12> cloud_layer_uniforms(const shared::CloudLayer& layer);

class CloudPass {
 public:
  // Needs a current GL context.
  CloudPass();

  // Draws `layer` over frame.target_framebuffer (its radiance), reading
  // frame's depth and surface textures, camera, rays and sun; the
  // atmosphere's uniform block bound at its binding; `sky_irradiance` the
  // technique's ground_irradiance() (0: none, estimated).
  void draw(const SkyFrame& frame, const shared::CloudLayer& layer, const CloudQuality& quality,
            GLuint sky_irradiance);

  // The last draw's clouds at full resolution: rgb what they added, alpha
  // their transmittance (which dims the stars behind them).
  GLuint clouds_texture() const { return full_.id(); }

 private:
  Program march_program_;
  Program upsample_program_;
  Program fill_program_;
  Program blend_program_;
  FullscreenPass pass_;
  int width_ = 0, height_ = 0, downsample_ = 0;
  Texture marched_, full_;  // RGBA32F: the marched pixels, and all of them
  Texture marched_keys_;    // RG32F: the marched pixels' cloud_ray_key
  Framebuffer marched_fbo_, full_fbo_;
};

}  // namespace planet
