#pragma once
// Hillaire 2020, "A Scalable and Production Ready Sky and Atmosphere
// Rendering Technique": a transmittance LUT, a multiple-scattering LUT, a
// sky-view LUT at the camera's altitude and aerial-perspective froxels,
// each a pass of the frame's PassGraph, recomputed only when what it
// depends on changed (its inputs: the model for the first two, the
// altitude and the sun's elevation within a stated step for the sky view,
// the exact view for the froxels), and a
// per-pixel march with the same multiple-scattering LUT where the LUTs
// cannot serve (high up and in space), or from outside the shell a
// space-view LUT for the camera's distance and sun (space_view_lut.glsl)
// where the planet fills enough of the frame. The multiple-scattering LUT sums the orders of
// scattering one by one on the paper's 2D table (technique "hillaire"), or
// takes the paper's Psi_ms = L_2 / (1 - f_ms) (technique "hillaire2020");
// the first also carries the glow of sunlight that the air scatters
// forward along the sun's path, past the table's degree (a
// forward-gain LUT). See hillaire_functions.glsl for why. The sky pass is
// split for a software rasteriser or drawn whole for a GPU, by the schedule
// (gl/schedule.h) the technique takes when built.
#include "atmosphere/gpu/hillaire/hillaire_programs.h"
#include "atmosphere/gpu/technique.h"
#include "gl/depth_probe.h"
#include "gl/fullscreen_pass.h"
#include "gl/pass_graph.h"
#include "gl/program.h"
#include "gl/schedule.h"
#include "gl/texture.h"

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace planet {

class HillaireTechnique final : public AtmosphereTechnique {
 public:
  // Which path draws the frame: chosen by altitude (with a blend between),
  // or forced, for measurements and tests.
  enum class Path { kByAltitude, kLuts, kPerPixel };
  enum class MultipleScattering { kOrders, kPaper };
  struct Settings {
    MultipleScattering multiple_scattering = MultipleScattering::kOrders;
    // False: single scattering alone (no orders above the first, no sky
    // light on the ground, no forward glow), to be measured against the
    // ground truth's first order.
    bool multiple = true;
    // The terrain's shadow in the air (the frame's shadow-height field): in
    // the froxels and the per-pixel march, and taken off the open sky.
    bool terrain_shadows = true;
    int sky_view_steps = 30;
    int per_pixel_steps = 40;
    int aerial_substeps = 2;     // per froxel slice
    double aerial_range = 32e3;  // metres, near the ground
    // The per-pixel path takes over between these altitudes, as fractions
    // of the atmosphere's thickness (60 and 80 km on Earth).
    double switch_start = 0.6;
    double switch_end = 0.8;
    Path path = Path::kByAltitude;
    // From outside the shell, on the per-pixel path alone and with no
    // terrain's shadow in the air, the sky pass reads the space-view LUT
    // (space_view_lut.glsl) instead of marching every pixel; false marches.
    bool space_view_lut = true;
    int space_view_steps = 40;  // the open-sky table's march, whole rays
    // ... where the shell's screen bound holds at least this many pixels:
    // marching the table costs about what marching this many pixels does
    // (`planet bench --benchmark_filter=HillaireSky`: 52 ms for the
    // table; the march 0.46 us a pixel from 400 km, whose bound is the
    // whole frame, against 0.04 for the lookup), so a small disk far off
    // is marched, as cheaply.
    double space_view_min_pixels = 120000.0;
    // The sky-view LUT is computed at the camera's altitude rounded to
    // this step of log2(altitude) and at the sun's zenith angle rounded to
    // this step, and reused while both round the same: the steps bound what
    // reuse changes (PassReuseGLTest.SkyViewReuseWithinItsSteps...
    // measures it on the canonical scenes). 0 computes it at the exact values.
    double sky_view_log2_altitude_step = 1.0 / 512.0;
    double sky_view_sun_zenith_step_deg = 0.0005;
    // False: every pass runs every frame, the sky view at the exact
    // altitude and sun (the steps above are not used): what reuse is
    // measured against.
    bool reuse_passes = true;
    // How the sky pass is split for the rasteriser (gl/schedule.h); empty:
    // current_schedule(), by the command's --schedule or the GL renderer.
    std::optional<Schedule> schedule;
  };
  explicit HillaireTechnique(Settings settings);
  HillaireTechnique() : HillaireTechnique(Settings{}) {}

  std::string name() const override {
    return settings_.multiple_scattering == MultipleScattering::kPaper ? "hillaire2020"
                                                                       : "hillaire";
  }
  void update(const AtmosphereModel& model) override;
  void prepare(GpuTimer& timer) override;
  void render(const SkyFrame& frame, GpuTimer& timer) override;
  GLuint ground_irradiance() const override {
    // Single scattering alone: the table, left at zero, says the sky gives
    // the ground no light.
    return settings_.multiple_scattering == MultipleScattering::kOrders || !settings_.multiple
               ? ground_irradiance_lut_.id()
               : 0;
  }

  bool takes_terrain_shadow() const override { return settings_.terrain_shadows; }
  const Settings& settings() const { return settings_; }
  Schedule schedule() const { return schedule_; }
  // Weight of the LUT path in the last frame (1: LUTs only, 0: per pixel).
  double lut_weight() const { return lut_weight_; }
  // Distance along the ray that the froxel volume covered in the last frame.
  double aerial_range() const { return aerial_range_; }
  // The fraction of the frame's pixels that the sky pass shaded in the last
  // frame (the rest, outside the shell's screen bound, were space).
  double shaded_fraction() const { return shaded_fraction_; }
  // Whether the last frame's sky pass read the space-view LUT.
  bool used_space_view() const { return used_space_view_; }
  // The altitude (metres above the bottom sphere) and the sun's zenith
  // angle (radians) that the sky-view LUT was last computed at.
  double sky_view_altitude() const { return sky_view_altitude_; }
  double sky_view_sun_zenith() const { return sky_view_sun_zenith_; }

  // The LUTs, for tests and debugging views.
  GLuint transmittance_lut() const { return transmittance_lut_.id(); }
  GLuint multiple_scattering_lut() const { return multiple_scattering_lut_.id(); }
  // The multiple-scattering LUT is kFieldParts tables of w x h side by side
  // (the terms of FieldMoments; w = kMultipleScatteringLutWidth over mu_s,
  // h = kMultipleScatteringLutHeight over altitude). Order n = 1 ...
  // kScatteringOrders of the last frame: the same parts on the order's grid
  // (w = hillaire::scattering_order_width(n), h = _height(n)) over h rows,
  // and E_n in the first w texels of row h; not filled with the paper's
  // LUT.
  GLuint scattering_order_lut(int n) const { return order_luts_[size_t(n - 1)].id(); }
  // The sky's irradiance on the ground per unit solar irradiance over the
  // sun's zenith cosine (one row, the multiple-scattering LUT's mu_s
  // mapping); zero with the paper's LUT, which has no such sum.
  GLuint ground_irradiance_lut() const { return ground_irradiance_lut_.id(); }
  // exp(-tau) forward_gain over (nu, tau) (hillaire_functions.glsl), for
  // the model's Mie g; not filled with the paper's LUT.
  GLuint forward_gain_lut() const { return forward_gain_lut_.id(); }
  GLuint sky_view_lut() const { return sky_view_lut_.id(); }
  GLuint aerial_scattering() const { return aerial_scattering_.id(); }
  GLuint aerial_transmittance() const { return aerial_transmittance_.id(); }

 private:
  struct FrameState;
  // The passes of prepare() and of render(), and what they run.
  std::vector<Pass> model_passes();
  void compute_multiple_scattering();
  FrameState frame_state(const SkyFrame& frame);
  void choose_path(double altitude);
  void round_sky_view_inputs(FrameState& s);
  bool sky_shadow(const FrameState& s) const;
  void bound_shaded_pixels(FrameState& s);
  std::vector<Pass> frame_passes(FrameState& s);
  void compute_sky_view_lut(const FrameState& s);
  bool froxels_needed(const FrameState& s);
  PassKey froxel_inputs(const FrameState& s) const;
  void compute_aerial_perspective(const FrameState& s);
  void compute_space_view_lut(const FrameState& s);
  void draw_space(const FrameState& s);
  void begin_space(const Program& program, const FrameState& s);
  void draw_sky(const FrameState& s);
  void begin_sky(const Program& program, const FrameState& s);
  void draw_by_kind(const Program& open_sky, const Program& surfaces, const FrameState& s,
                    const std::function<void(const Program&)>& bind);
  void bind_space_view(const Program& program, const FrameState& s);
  void draw_space_view_sky(const FrameState& s);
  void draw_sky_in_parts(const FrameState& s);
  void draw_march_tiles(const FrameState& s);

  Settings settings_;
  AtmosphereModel model_;
  Schedule schedule_;
  HillairePrograms programs_;
  bool grey_mie_ = false;  // the model's Mie scattering is the same in every channel
  Buffer march_tiles_;  // the indirect draw's command, then the tiles
  size_t march_tiles_bytes_ = 0;
  Texture transmittance_lut_, multiple_scattering_lut_, ground_irradiance_lut_, forward_gain_lut_,
      sky_view_lut_, aerial_scattering_, aerial_transmittance_, aerial_shadow_loss_,
      space_open_sky_, space_scattering_, space_transmittance_;
  std::array<Texture, 6> order_luts_;  // kScatteringOrders
  Buffer block_;
  FullscreenPass sky_pass_;
  DepthProbe surface_probe_;
  bool prepared_ = false;  // prepare() ran since the last render()
  PassKey model_key_;      // the model's block: every pass depends on it
  PassGraph graph_;
  double sky_view_altitude_ = 0.0, sky_view_sun_zenith_ = 0.0;
  double lut_weight_ = 1.0;
  double aerial_range_ = 0.0;
  double shaded_fraction_ = 1.0;
  bool used_space_view_ = false;
};

}  // namespace planet
