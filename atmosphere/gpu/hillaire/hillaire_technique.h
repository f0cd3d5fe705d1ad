#pragma once
// Hillaire 2020, "A Scalable and Production Ready Sky and Atmosphere
// Rendering Technique": a transmittance LUT, a multiple-scattering LUT
// (Psi_ms = L_2 / (1 - f_ms)), a sky-view LUT at the camera's altitude and
// aerial-perspective froxels, all recomputed every frame from the current
// model, and a per-pixel march with the same multiple-scattering LUT where
// the LUTs cannot serve (high up and in space).
#include "atmosphere/gpu/technique.h"
#include "render/gl/program.h"
#include "render/gl/texture.h"

namespace planet {

class HillaireTechnique final : public AtmosphereTechnique {
 public:
  // Which path draws the frame: chosen by altitude (with a blend between),
  // or forced, for measurements and tests.
  enum class Path { kByAltitude, kLuts, kPerPixel };
  struct Settings {
    int sky_view_steps = 30;
    int per_pixel_steps = 40;
    int aerial_substeps = 2;  // per froxel slice
    double aerial_range = 32e3;  // metres, near the ground
    // The per-pixel path takes over between these altitudes, as fractions
    // of the atmosphere's thickness (60 and 80 km on Earth).
    double switch_start = 0.6;
    double switch_end = 0.8;
    Path path = Path::kByAltitude;
  };
  explicit HillaireTechnique(Settings settings);
  HillaireTechnique() : HillaireTechnique(Settings{}) {}

  std::string name() const override { return "hillaire"; }
  void update(const AtmosphereModel& model) override;
  void render(const SkyFrame& frame, GpuTimer& timer) override;

  const Settings& settings() const { return settings_; }
  // Weight of the LUT path in the last frame (1: LUTs only, 0: per pixel).
  double lut_weight() const { return lut_weight_; }
  // Distance along the ray that the froxel volume covered in the last frame.
  double aerial_range() const { return aerial_range_; }

  // The LUTs, for tests and debugging views.
  GLuint transmittance_lut() const { return transmittance_lut_.id(); }
  GLuint multiple_scattering_lut() const { return multiple_scattering_lut_.id(); }
  GLuint sky_view_lut() const { return sky_view_lut_.id(); }
  GLuint aerial_scattering() const { return aerial_scattering_.id(); }
  GLuint aerial_transmittance() const { return aerial_transmittance_.id(); }

 private:
  Settings settings_;
  AtmosphereModel model_;
  Program transmittance_program_, multiple_scattering_program_, sky_view_program_,
      aerial_program_, sky_program_;
  Texture transmittance_lut_, multiple_scattering_lut_, sky_view_lut_, aerial_scattering_,
      aerial_transmittance_;
  Buffer block_;
  VertexArray empty_vao_;
  double lut_weight_ = 1.0;
  double aerial_range_ = 0.0;
};

}  // namespace planet
