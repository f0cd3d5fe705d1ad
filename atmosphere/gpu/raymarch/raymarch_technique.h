#pragma once
// Nishita et al. 1993: per pixel, a ray march along the view ray with, at
// every sample, a second march toward the sun; single scattering only. The
// brute-force baseline every other technique is compared against for speed.
#include "atmosphere/gpu/technique.h"
#include "gl/fullscreen_pass.h"
#include "gl/pass_graph.h"
#include "gl/program.h"
#include "gl/texture.h"

namespace planet {

class RaymarchTechnique final : public AtmosphereTechnique {
 public:
  struct Steps {
    int view = 32;
    int light = 16;
    // The terrain's shadow in the air (the frame's shadow-height field).
    bool terrain_shadows = true;
  };
  explicit RaymarchTechnique(Steps steps);
  RaymarchTechnique() : RaymarchTechnique(Steps{}) {}

  std::string name() const override { return "raymarch"; }
  void update(const AtmosphereModel& model) override;
  void render(const SkyFrame& frame, GpuTimer& timer) override;
  bool takes_terrain_shadow() const override { return steps_.terrain_shadows; }

 private:
  void draw_sky(const SkyFrame& frame);

  Steps steps_;
  Program program_;
  Buffer block_;
  FullscreenPass pass_;
  PassGraph graph_;
};

}  // namespace planet
