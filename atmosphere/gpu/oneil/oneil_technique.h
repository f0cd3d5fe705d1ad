#pragma once
// O'Neil 2005, "Accurate Atmospheric Scattering" (GPU Gems 2, ch. 16):
// single scattering summed per vertex at a few samples along each ray, with
// the optical depths from a scale function instead of a second march
// (atmosphere/shaders/oneil_functions.glsl). The sky is a dome on the
// atmosphere's top sphere; the surfaces, which reach the technique as depth
// and radiance, get their aerial perspective on a screen-space grid. The
// scale function is fitted to the body's own Rayleigh and Mie scale heights
// when the model changes (atmosphere/math/oneil_math.h), or is the
// chapter's fixed polynomial.
#include "atmosphere/gpu/atmosphere_block.h"
#include "atmosphere/gpu/technique.h"
#include "atmosphere/math/oneil_math.h"
#include "gl/fullscreen_pass.h"
#include "gl/pass_graph.h"
#include "gl/program.h"
#include "gl/texture.h"

namespace planet {

class OneilTechnique final : public AtmosphereTechnique {
 public:
  enum class Scale { kFitted, kChapter };
  struct Settings {
    int samples = 8;  // along each ray (see the registry)
    int dome = 48;    // the dome's rings; twice as many segments around
    int cell = 8;     // pixels between the grid's vertices
    Scale scale = Scale::kFitted;
    // The chapter's 1 - exp(-exposure L) in place of the frame's tone map.
    bool chapter_exposure = false;
  };
  explicit OneilTechnique(Settings settings);
  OneilTechnique() : OneilTechnique(Settings{}) {}

  std::string name() const override { return "oneil"; }
  void update(const AtmosphereModel& model) override;
  void render(const SkyFrame& frame, GpuTimer& timer) override;
  bool writes_display_values() const override { return settings_.chapter_exposure; }

  const Settings& settings() const { return settings_; }
  // The fitted scale functions of the model last given, and their errors.
  const oneil::BodyScales& fitted() const { return fitted_; }

 private:
  void set_frame_uniforms(const Program& program, const SkyFrame& frame) const;
  // The passes of a frame, in order.
  void classify(const SkyFrame& frame);
  int dome_rings(const SkyFrame& frame) const;
  void draw_dome(const SkyFrame& frame);
  void draw_grid(const SkyFrame& frame);
  void draw_own_rays(const SkyFrame& frame);

  Settings settings_;
  AtmosphereModel model_;
  bool has_model_ = false;
  AtmosphereBlock block_values_{};
  oneil::BodyScales fitted_;
  oneil::OneilScale rayleigh_, mie_;
  Buffer block_;
  Program classify_program_, dome_program_, ground_program_, pixel_program_;
  FullscreenPass fullscreen_;
  VertexArray dome_vao_, grid_vao_;
  Buffer dome_indices_, grid_indices_;
  int grid_width_ = 0, grid_height_ = 0;  // the grid's cells, columns and rows
  PassGraph graph_;
};

}  // namespace planet
