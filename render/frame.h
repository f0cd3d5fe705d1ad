#pragma once
// One frame of the planet: opaque surfaces into an HDR target with depth,
// then the atmosphere technique over them, then exposure and tone mapping
// into an 8-bit target. Everything it draws is placed relative to the
// camera: body-frame positions in double never reach the GPU.
#include "atmosphere/gpu/technique.h"
#include "atmosphere/model.h"
#include "gl/fullscreen_pass.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/timer.h"
#include "render/star_field.h"
#include "sim/body.h"
#include "sim/camera.h"
#include "terrain/gpu/terrain_renderer.h"
#include "terrain/sun_shadow_field.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace planet {

// The terrain's shadow in the air reaches a camera up to this altitude
// above the bottom sphere (metres), fading out over the last 20 km: higher,
// the shafts of a patch of ground are too small to show.
constexpr double kTerrainShadowTop = 50e3;

struct FrameStats {
  std::vector<PassTiming> passes;  // GPU time per pass
  double total_gpu_ms() const;
};

class FrameRenderer {
 public:
  // Needs a current GL 4.5 context.
  FrameRenderer(int width, int height);
  ~FrameRenderer();

  // The body to draw, with its atmosphere (none for an airless body) drawn
  // by `technique`.
  void set_body(const Body& body, std::optional<AtmosphereModel> atmosphere,
                std::unique_ptr<AtmosphereTechnique> technique);

  // A new model for the body's atmosphere (a slider moved): the technique
  // takes it, and the next frame shows it. Only for a body drawn with an
  // atmosphere.
  void set_atmosphere(const AtmosphereModel& atmosphere);

  FrameStats render(const Camera& camera, const glm::dvec3& sun_dir_body, double exposure);

  // Another technique for the body's atmosphere, taken as it is (the caller
  // has given it the current model); returns the one it replaces.
  std::unique_ptr<AtmosphereTechnique> swap_technique(std::unique_ptr<AtmosphereTechnique> technique);
  AtmosphereTechnique* technique() const { return technique_.get(); }
  // While a switch of technique fades: `previous` draws each frame too
  // (surfaces and atmosphere, as it would alone), and its image is laid
  // over the technique's at `weight` (0 to 1), in linear radiance. nullptr
  // or a weight of 0 ends it; so does a pair of which one writes display
  // values and the other radiance. The caller keeps `previous` alive.
  void set_fade(AtmosphereTechnique* previous, double weight);

  // Anti-aliasing of the surfaces' edges: `samples` per pixel (1: none,
  // the default, one ray through each pixel's centre as the path tracer
  // traces it; capture and fly take 4). The surfaces are drawn
  // multisampled and resolved to one surface per pixel with its coverage;
  // after the atmosphere, a partly covered pixel takes the rest from the
  // open sky beside it. SystemError for a count the GL cannot give.
  void set_antialiasing(int samples);
  int antialiasing() const { return samples_; }
  // The tone-mapped image's edges smoothed (FXAA, render/shaders/
  // smooth_edges.frag), off by default: for a window on a GL where
  // multisampling costs too much (llvmpipe), in its place.
  void set_smooth_edges(bool on) { smooth_edges_ = on; }
  bool smooth_edges() const { return smooth_edges_; }

  // Terrain settings, taken by the next set_body.
  void set_terrain_options(const TerrainOptions& options) { terrain_options_ = options; }
  // Wait up to this long for every terrain tile a frame needs, so that a
  // frame is complete and the same on every run (the default: capture,
  // tests, benchmarks); 0 draws what is resident and never waits, as a
  // window must.
  void set_terrain_wait(double seconds) { terrain_wait_s_ = seconds; }
  const TerrainStats& terrain_stats() const { return terrain_stats_; }
  // Each pass waits for the GL before and after it, and reports its wall
  // time too (PassTiming::wall_ms): for benchmarks.
  void set_synchronous_timing(bool synchronous) { timer_.set_synchronous(synchronous); }
  TerrainRenderer* terrain() { return terrain_.get(); }
  // False: the surfaces are lit by the sun alone, without the sky's light
  // (the second order of scattering): with a technique that draws single
  // scattering alone, the frame is the first order, as `reference
  // --max-order 1` traces it.
  void set_surface_sky_light(bool on) { surface_sky_light_ = on; }
  // False: the terrain casts no shadow from the sun, on the ground or in
  // the air (the default is on). Its shadow in the air is computed up to
  // kTerrainShadowTop above the bottom sphere (fading out over the last
  // 20 km) and drawn by the techniques that take it (their
  // terrain_shadows quality parameter).
  void set_terrain_shadows(bool on) { terrain_shadows_ = on; }
  bool terrain_shadows() const { return terrain_shadows_; }

  // The stars behind the sky (star_field.h), off by default: the
  // techniques' accuracy is measured on the sky alone. The orientation
  // turns the catalogue's ICRF into the body's frame for the next frames
  // (body_from_icrf).
  void set_stars(bool on);
  bool stars() const { return stars_on_; }
  void set_star_orientation(const glm::dmat3& body_from_icrf) { body_from_icrf_ = body_from_icrf; }

  // Glare: the eye's scattered light around very bright pixels (the sun),
  // off by default (captures and the lab measure the sky alone); fly turns
  // it on. See draw_glare.
  void set_glare(bool on) { glare_ = on; }
  bool glare() const { return glare_; }

  // Automatic exposure: each frame's own, set from its mean luminance
  // (auto_exposure.comp) in place of the one render() is given. Off by
  // default.
  void set_auto_exposure(bool on) { auto_exposure_ = on; }
  bool auto_exposure() const { return auto_exposure_; }
  // The exposure the last frame was tone-mapped with: the one given, or
  // the measured one (read back from the GL) when automatic.
  double last_exposure() const;

  // False: the frame tells the technique nothing that would let it leave
  // a pass or a pixel out (no surface distance, no screen bound of the
  // shell), so every pass and pixel is computed: what pruning is checked
  // against.
  void set_view_pruning(bool on) { view_pruning_ = on; }

  int width() const { return width_; }
  int height() const { return height_; }
  // Linear HDR radiance, RGBA float, rows bottom-up as GL stores them.
  std::vector<float> read_hdr() const;
  // Tone-mapped sRGB, RGBA8, rows bottom-up.
  std::vector<uint8_t> read_ldr() const;
  // The distance along each pixel's ray to the surface drawn there, metres
  // (+inf where there is none), for the last frame of `camera`; rows
  // bottom-up.
  std::vector<float> read_distance(const Camera& camera) const;
  GLuint ldr_texture() const { return ldr_.id(); }

 private:
  void draw_surfaces(const Camera& camera, const glm::dvec3& sun_dir_body,
                     const AtmosphereTechnique* technique);
  void draw_atmosphere(const Camera& camera, const glm::dvec3& sun_dir_body, double exposure,
                       AtmosphereTechnique& technique);
  // The frame's linear radiance: the atmosphere's target, or for an
  // airless body the surfaces' own.
  const Texture& radiance() const;
  // With anti-aliasing: the multisampled surfaces into surface_ and depth_,
  // timed as `pass`.
  void resolve_surfaces(const char* pass);
  // With anti-aliasing: the partly covered pixels of `target` (the
  // radiance's framebuffer) take the rest from the open ones beside them,
  // timed as `pass`.
  void blend_surface_edges(GLuint target, const char* pass);

  // The terrain's shadow in the air for this frame (none when off, over a
  // smooth body or high up), computed when the camera's patch or the sun
  // moved, timed as the pass "terrain_shadow".
  SkyTerrainShadow terrain_shadow(const glm::dvec3& camera_atmo, const glm::dvec3& sun_atmo,
                                  const glm::dvec3& atmo_scale);

  // The stars, then the automatic exposure, into the frame's radiance.
  void draw_stars(const Camera& camera, double exposure);
  void measure_exposure();
  // The glare's pyramid of the frame's radiance (glare_up_[0] its sum),
  // timed as the pass "glare".
  void draw_glare();

  int width_, height_;
  // ground_below_: how far the surface under each pixel lies below the
  // datum (terrain.frag), for the atmosphere's air in front of it.
  Texture depth_, surface_, ground_below_, hdr_, ldr_;
  // The sky target's stencil: cleared before the technique draws, for the
  // technique's own masks (which pixels each of its passes shades).
  Texture sky_stencil_;
  // surface_draw_fbo_: the surfaces' pass (and the resolve), which also
  // writes ground_below_; surface_fbo_: the passes after it.
  Framebuffer surface_fbo_, surface_draw_fbo_, hdr_fbo_, ldr_fbo_;
  Program tonemap_program_;
  // Anti-aliasing: the multisampled surfaces, resolved into surface_ and
  // depth_ (made by set_antialiasing).
  int samples_ = 1;
  Texture surface_ms_, ground_below_ms_, depth_ms_;
  Framebuffer surface_ms_fbo_;
  Program resolve_program_, edges_program_;
  Buffer atmosphere_block_;
  FullscreenPass tonemap_pass_;
  TerrainOptions terrain_options_;
  std::unique_ptr<TerrainRenderer> terrain_;
  TerrainStats terrain_stats_;
  double terrain_wait_s_ = 300.0;
  bool surface_sky_light_ = true;
  bool terrain_shadows_ = true;
  bool view_pruning_ = true;
  std::unique_ptr<SunShadowField> shadow_field_;  // made by set_body
  Texture shadow_texture_;
  uint64_t shadow_uploaded_ = 0;  // the field's version the texture holds

  Body body_;
  std::optional<AtmosphereModel> atmosphere_;
  std::unique_ptr<AtmosphereTechnique> technique_;
  AtmosphereTechnique* fade_from_ = nullptr;
  double fade_weight_ = 0;
  Texture fade_;  // the previous technique's frame, made on the first fade
  Program fade_program_;
  bool stars_on_ = false;
  std::unique_ptr<StarField> stars_;  // made on the first set_stars(true)
  glm::dmat3 body_from_icrf_{1.0};
  bool auto_exposure_ = false;
  double exposure_ = 1.0;           // the last frame's, as given
  bool exposure_measured_ = false;  // the last frame's was measured
  Program exposure_program_;
  Buffer exposure_block_;
  bool glare_ = false;
  bool smooth_edges_ = false;
  Texture ldr_unsmoothed_;  // the tone map's, made on the first smoothing
  Program smooth_edges_program_;
  // Half the frame's size and down by halves, made on the first glare.
  std::vector<Texture> glare_down_, glare_up_;
  std::vector<Framebuffer> glare_down_fbo_, glare_up_fbo_;
  Program glare_down_program_, glare_up_program_;
  GpuTimer timer_;
};

}  // namespace planet
