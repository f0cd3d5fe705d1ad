// A headless target for drawing the terrain alone: a float colour texture,
// a reversed-z depth texture and an atmosphere block of zeros (no air), so
// that a test sees the surfaces' own radiance.
#pragma once

#include "atmosphere/gpu/atmosphere_block.h"
#include "gl/context.h"
#include "gl/texture.h"
#include "terrain/gpu/terrain_renderer.h"

#include <memory>
#include <vector>

namespace planet {

class TerrainTarget {
 public:
  TerrainTarget(int width, int height)
      : width_(width), height_(height), context_(GlContext::create_headless()) {
    color_ = make_texture_2d(GL_RGBA32F, width, height);
    depth_ = make_texture_2d(GL_DEPTH_COMPONENT32F, width, height);
    fbo_ = make_framebuffer(color_.id(), depth_.id());
    AtmosphereBlock zero{};
    block_ = make_buffer(sizeof(zero), &zero);
  }

  // Draws the terrain over `background`; returns RGBA, bottom row first.
  std::vector<float> draw(TerrainRenderer& terrain, const Camera& camera, const glm::dvec3& sun,
                          const float background[4]) {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    begin_reversed_z(fbo_.id(), width_, height_, background);
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
    TerrainLighting lighting;
    lighting.sun_dir_body = sun;
    terrain.draw(camera, width_, height_, lighting);
    glDisable(GL_DEPTH_TEST);
    return read_texture_rgba32f(color_.id(), width_, height_);
  }

 private:
  int width_, height_;
  std::unique_ptr<GlContext> context_;
  Texture color_, depth_;
  Framebuffer fbo_;
  Buffer block_;
};

}  // namespace planet
