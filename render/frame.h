#pragma once
// One frame of the planet: opaque surfaces into an HDR target with depth,
// then the atmosphere technique over them, then exposure and tone mapping
// into an 8-bit target. Everything it draws is placed relative to the
// camera: body-frame positions in double never reach the GPU.
#include "atmosphere/gpu/technique.h"
#include "atmosphere/model.h"
#include "clouds/gpu/cloud_pass.h"
#include "gl/fullscreen_pass.h"
#include "gl/pass_graph.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/timer.h"
#include "render/glare.h"
#include "render/star_field.h"
#include "render/surface_antialiasing.h"
#include "sim/body.h"
#include "sim/camera.h"
#include "terrain/gpu/terrain_renderer.h"
#include "terrain/sun_shadow_field.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
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

// How a FrameRenderer draws its frames, set in one call (set_options).
// The defaults are the lab's: the sky alone, one ray through each pixel's
// centre as the path tracer traces it, at the exposure given; capture and
// fly set what their flights and windows ask for.
struct FrameOptions {
  // Anti-aliasing of the surfaces' edges: samples per pixel (1: none, one
  // ray through each pixel's centre as the path tracer traces it). The
  // surfaces are lit once a pixel, their coverage and depth counted per
  // sample, and resolved to one surface per pixel with its coverage; after
  // the atmosphere, a partly covered pixel takes the rest from the open sky
  // beside it. A pixel a surface covers whole is as at one sample.
  // SystemError for a count the GL cannot give.
  int antialiasing = 1;
  // The tone-mapped image's edges smoothed (FXAA, render/shaders/
  // smooth_edges.frag): for a window on a GL where multisampling costs too
  // much (llvmpipe), in its place.
  bool smooth_edges = false;
  // Terrain settings, taken by the next set_body.
  TerrainOptions terrain;
  // Wait up to this long for every terrain tile a frame needs, so that a
  // frame is complete and the same on every run (capture, tests,
  // benchmarks); 0 draws what is resident and never waits, as a window
  // must.
  double terrain_wait_s = 300.0;
  // Each pass waits for the GL before and after it, and reports its wall
  // time too (PassTiming::wall_ms): for benchmarks.
  bool synchronous_timing = false;
  // False: the surfaces are lit by the sun alone, without the sky's light
  // (the second order of scattering): with a technique that draws single
  // scattering alone, the frame is the first order, as `reference
  // --max-order 1` traces it.
  bool surface_sky_light = true;
  // False: the terrain casts no shadow from the sun, on the ground or in
  // the air. Its shadow in the air is computed up to kTerrainShadowTop
  // above the bottom sphere (fading out over the last 20 km) and drawn by
  // the techniques that take it (their terrain_shadows quality parameter).
  bool terrain_shadows = true;
  // The stars behind the sky (star_field.h): off for the techniques'
  // accuracy, measured on the sky alone.
  bool stars = false;
  // Glare (glare.h): the eye's scattered light around very bright pixels
  // (the sun); captures and the lab measure the sky alone, fly turns it on.
  bool glare = false;
  // Automatic exposure: each frame's own, set from its mean luminance
  // (auto_exposure.comp) in place of the one render() is given.
  bool auto_exposure = false;
  // False: the frame tells the technique nothing that would let it leave
  // a pass or a pixel out (no surface distance, no screen bound of the
  // shell), so every pass and pixel is computed: what pruning is checked
  // against.
  bool view_pruning = true;
  // The body's cloud layer (its file's "clouds"; clouds/gpu/cloud_pass.h)
  // over the sky and the ground, at `cloud_quality`: off for the lab's
  // clear skies and for the flights that do not ask for it.
  bool clouds = false;
  CloudQuality cloud_quality;
};

// A frame is a graph of passes (gl/pass_graph.h), in this order:
//   atmosphere_tables  the technique's model-wide tables (they time their own passes)
//   fade:frame         while a switch of technique fades, the previous technique's
//                      frame, as below with "fade:" before each name, kept in a texture
//   surface            the opaque surfaces, lit with the tables' sky light once a pixel
//                      (with anti-aliasing, their coverage drawn per sample first)
//   resolve            with anti-aliasing, the lit surfaces and their coverage to one per pixel
//   terrain_shadow     the terrain's shadow in the air (CPU), for a technique that draws it
//   atmosphere         sky, sun and aerial perspective (the technique times its own passes)
//   clouds             the body's cloud layer over them, the air in front of it
//   antialias          with anti-aliasing, the surfaces' edges against the sky
//   fade               the previous technique's frame laid over this one
//   stars, exposure, glare, tonemap, smooth_edges
// Each pass the frame does not need (its option off, no air, no fade) is
// listed as skipped in the frame's timings.
class FrameRenderer {
 public:
  // Needs a current GL 4.5 context.
  FrameRenderer(int width, int height);
  ~FrameRenderer();

  // Every option at once; the next frame draws with them.
  void set_options(const FrameOptions& options);
  const FrameOptions& options() const { return options_; }

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
  std::unique_ptr<AtmosphereTechnique> swap_technique(
      std::unique_ptr<AtmosphereTechnique> technique);
  AtmosphereTechnique* technique() const { return technique_.get(); }
  // While a switch of technique fades: `previous` draws each frame too
  // (surfaces and atmosphere, as it would alone), and its image is laid
  // over the technique's at `weight` (0 to 1), in linear radiance. nullptr
  // or a weight of 0 ends it; so does a pair of which one writes display
  // values and the other radiance. The caller keeps `previous` alive.
  void set_fade(AtmosphereTechnique* previous, double weight);
  // Turns the star catalogue's ICRF into the body's frame for the next
  // frames (body_from_icrf).
  void set_star_orientation(const glm::dmat3& body_from_icrf) { body_from_icrf_ = body_from_icrf; }
  // The Moon before the sun for the next frames: its centre in the body
  // frame and its radius, metres (0: none, the default).
  void set_moon(const glm::dvec3& pos_body, double radius) {
    moon_pos_body_ = pos_body;
    moon_radius_ = radius;
  }

  const TerrainStats& terrain_stats() const { return terrain_stats_; }
  TerrainRenderer* terrain() { return terrain_.get(); }
  // The exposure the last frame was tone-mapped with: the one given, or
  // the measured one (read back from the GL) when automatic.
  double last_exposure() const;

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
  struct Frame;  // one render()'s camera, sun, exposure and what it draws
  // The frame's passes (the list above), and the ones that draw its
  // radiance with `technique` (prefix "fade:" for the fade's).
  std::vector<Pass> passes(const Frame& f);
  std::vector<Pass> radiance_passes(const Frame& f, AtmosphereTechnique* technique,
                                    const std::string& prefix);
  std::vector<Pass> image_passes(const Frame& f);

  void draw_surfaces(const Frame& f, const AtmosphereTechnique* technique);
  // The Moon's radius if it may cover part of the sun from some point the
  // frame draws, else 0: a frame far from an eclipse then pays nothing
  // for the Moon, and the techniques keep their reuse of passes.
  double eclipsing_moon_radius(const Frame& f) const;
  void draw_atmosphere(const Frame& f, AtmosphereTechnique& technique);
  // Whether the frame's clouds pass runs (and dims the stars).
  bool clouds_drawn(const Frame& f) const;
  void draw_clouds(const Frame& f, const AtmosphereTechnique& technique);
  // The terrain's shadow in the air for the frame, needed by a technique
  // that draws it but for none when off, over a smooth body or high up;
  // updated when the camera's patch or the sun moved (timed as `pass`, on
  // the CPU), then handed to the technique.
  bool terrain_shadow_needed(const Frame& f, const AtmosphereTechnique* technique) const;
  void update_terrain_shadow(const Frame& f, const std::string& pass);
  SkyTerrainShadow terrain_shadow(const Frame& f) const;
  void draw_stars(const Frame& f);
  void tonemap(const Frame& f);
  // The frame's linear radiance: the atmosphere's target, or for an
  // airless body the surfaces' own.
  const Texture& radiance() const;

  int width_, height_;
  FrameOptions options_;
  PassGraph graph_, fade_graph_;
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
  // With anti-aliasing, the lit surfaces and their multisampled coverage,
  // resolved into surface_ and depth_ (made by set_options).
  std::unique_ptr<SurfaceAntialiasing> multisampled_;
  Buffer atmosphere_block_;
  glm::dvec3 moon_pos_body_{0.0};
  double moon_radius_ = 0;
  FullscreenPass tonemap_pass_;
  std::unique_ptr<TerrainRenderer> terrain_;
  TerrainStats terrain_stats_;
  std::unique_ptr<SunShadowField> shadow_field_;  // made by set_body
  Texture shadow_texture_;
  uint64_t shadow_uploaded_ = 0;  // the field's version the texture holds

  Body body_;
  std::optional<AtmosphereModel> atmosphere_;
  std::unique_ptr<AtmosphereTechnique> technique_;
  std::optional<shared::CloudLayer> clouds_;  // the body's, in atmosphere space
  std::unique_ptr<CloudPass> cloud_pass_;     // made on the first frame with clouds
  AtmosphereTechnique* fade_from_ = nullptr;
  double fade_weight_ = 0;
  Texture fade_;  // the previous technique's frame, made on the first fade
  Program fade_program_;
  std::unique_ptr<StarField> stars_;  // made on the first frame with stars
  glm::dmat3 body_from_icrf_{1.0};
  double exposure_ = 1.0;           // the last frame's, as given
  bool exposure_measured_ = false;  // the last frame's was measured
  Program exposure_program_;
  Buffer exposure_block_;
  Texture ldr_unsmoothed_;  // the tone map's, made on the first smoothing
  Program smooth_edges_program_;
  std::unique_ptr<GlarePyramid> glare_;  // made on the first glare
  GpuTimer timer_;
};

}  // namespace planet
