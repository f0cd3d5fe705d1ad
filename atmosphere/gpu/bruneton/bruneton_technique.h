#pragma once
// Bruneton and Neyret 2008, "Precomputed Atmospheric Scattering", as
// reworked in Bruneton's 2017 implementation: a transmittance table (2D),
// single and multiple scattering over (r, mu, mu_s, nu) packed in a 3D
// texture, and the ground's irradiance (2D), with the orders of scattering
// iterated on the GPU, each from the one before. The tables depend on the
// model and the quality alone: they are precomputed when the model changes
// (order k of N shown with the time left), kept on disk by a hash of both
// (bruneton_cache.h), and every frame only reads them.
#include "atmosphere/gpu/technique.h"
#include "gl/fullscreen_pass.h"
#include "gl/pass_graph.h"
#include "gl/program.h"
#include "gl/schedule.h"
#include "gl/texture.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace planet {

class BrunetonTechnique final : public AtmosphereTechnique {
 public:
  struct Settings {
    int transmittance_width = 256, transmittance_height = 64;
    int irradiance_width = 64, irradiance_height = 16;
    // The 4D scattering table. Bruneton's 32 x 128 x 32 x 8 left the noon sky
    // 3.5 % off in red (its mu_s mapping has 4 of 32 texels for the sun 30
    // deg up or higher) and the limb from 400 km 3.5 % (the lowest 8 km of
    // air takes 2.5 of the 64 texels of view cosine above the horizon):
    // 64 and 256 bring both to 1.3-1.7 %.
    int r = 32, mu = 256, mu_s = 64, nu = 8;
    int orders = 4;
    bool half = false;      // 16-bit floats for the scattering tables
    bool combined = false;  // single Mie's red in the scattering's alpha (Bruneton's default)
    int integration_steps = 50;  // along each ray of single and multiple scattering
    int sphere_samples = 16;     // zenith angles of the density's and irradiance's gathers
    int transmittance_steps = 100;
    // The orders past the last as a geometric series (ours; Bruneton stops).
    bool tail = true;
    // How the frame's pixels are split (gl/schedule.h): by the stencil's
    // classes, a program each (software), or one program for all (plain);
    // empty: current_schedule().
    std::optional<Schedule> schedule;
  };
  explicit BrunetonTechnique(Settings settings);
  // The bytes one model's tables of these settings take in the disk cache
  // (as 32-bit floats whatever the GPU keeps), header and checksum aside.
  static uintmax_t table_file_bytes(const Settings& s);
  BrunetonTechnique() : BrunetonTechnique(Settings{}) {}

  std::string name() const override { return "bruneton"; }
  void update(const AtmosphereModel& model) override;
  // The same tables, a layer of a pass a slice (see TableBuild).
  std::unique_ptr<TableBuild> update_in_slices(const AtmosphereModel& model) override;
  void render(const SkyFrame& frame, GpuTimer& timer) override;
  GLuint ground_irradiance() const override { return ground_irradiance_.id(); }

  const Settings& settings() const { return settings_; }
  Schedule schedule() const { return schedule_; }
  // The tables came from the disk cache in the last update, not a precompute.
  bool from_cache() const { return from_cache_; }
  // Wall time of the last precompute, one entry per order, each ending
  // with glFinish: the first holds the transmittance and direct irradiance
  // with order 1 (single scattering), then orders 2 to N (and the tail
  // with the last). Empty when cached.
  const std::vector<double>& precompute_seconds() const { return precompute_seconds_; }

  // The tables, for tests: RGBA float.
  GLuint transmittance_table() const { return transmittance_.id(); }  // optical depth
  GLuint scattering_table() const { return scattering_.id(); }
  GLuint single_mie_table() const { return single_mie_.id(); }
  GLuint irradiance_table() const { return irradiance_.id(); }
  // The smallest sun zenith cosine the tables hold, from the model's shell.
  double mu_s_min() const { return mu_s_min_; }

  // The cache key of a model at this quality.
  std::string cache_key(const AtmosphereModel& model) const;

 private:
  class Build;
  void make_ground_irradiance();
  void set_frame_uniforms(const SkyFrame& frame);
  void draw_sky(const SkyFrame& frame);
  void draw_aerial();
  void draw_every_pixel(const SkyFrame& frame);
  std::vector<std::string> defines(std::vector<std::string> more) const;

  Settings settings_;
  Schedule schedule_;
  std::string key_;
  AtmosphereModel model_;
  double mu_s_min_ = -0.2;
  Buffer block_;
  Texture transmittance_, irradiance_, scattering_, single_mie_, ground_irradiance_;
  // The stencil's classes 1 to 3, then the passes (bruneton_sky.frag);
  // with the plain schedule, the one pass for every pixel alone.
  std::array<Program, 3> classify_programs_;
  Program sky_program_, aerial_program_, horizon_program_, all_program_;
  FullscreenPass sky_pass_;
  PassGraph graph_;
  bool from_cache_ = false;
  std::vector<double> precompute_seconds_;
};

// The smallest sun zenith cosine at which a point of the shell still sees
// the sun over the planet's limb, with a margin: the tables go no lower.
double bruneton_mu_s_min(const AtmosphereModel& model);

}  // namespace planet
