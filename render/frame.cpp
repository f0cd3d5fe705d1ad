#include "render/frame.h"

#include "atmosphere/atmosphere_inputs.h"
#include "atmosphere/atmosphere_space.h"
#include "atmosphere/gpu/atmosphere_block.h"
#include "core/error.h"
#include "gl/context.h"
#include "gl/driver_watch.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace planet {

namespace {

// The glare: the light the eye scatters around a bright source, as the CIE
// disability glare equation gives it (Vos 2003, after Stiles and Holladay):
// a veil of 10 E / theta^2 (theta in degrees) per steradian for an
// illuminance E, which puts the same share of the light into each octave of
// theta: 10 x 2 pi ln 2 / (180 / pi)^2 = 1.33 %. Each level of the pyramid
// is one octave, from a pixel or two outwards.
constexpr double kGlarePerOctave = 10.0 * 2.0 * M_PI * M_LN2 / ((180.0 / M_PI) * (180.0 / M_PI));
constexpr int kGlareOctaves = 6;

}  // namespace

double FrameStats::total_gpu_ms() const {
  double sum = 0;
  for (const auto& p : passes) sum += p.gpu_ms;
  return sum;
}

FrameRenderer::FrameRenderer(int width, int height)
    : width_(width),
      height_(height),
      depth_(make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)),
      surface_(make_texture_2d(GL_RGBA32F, width, height)),
      ground_below_(make_texture_2d(GL_R32F, width, height)),
      hdr_(make_texture_2d(GL_RGBA32F, width, height)),
      ldr_(make_texture_2d(GL_RGBA8, width, height)),
      sky_stencil_(make_texture_2d(GL_STENCIL_INDEX8, width, height)),
      surface_fbo_(make_framebuffer(surface_.id(), depth_.id())),
      surface_draw_fbo_(make_framebuffer({surface_.id(), ground_below_.id()}, depth_.id())),
      hdr_fbo_(make_framebuffer(hdr_.id(), 0, sky_stencil_.id())),
      ldr_fbo_(make_framebuffer(ldr_.id(), 0)),
      tonemap_program_(
          Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/tonemap.frag")),
      atmosphere_block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
  AtmosphereBlock zero{};
  glNamedBufferSubData(atmosphere_block_.id(), 0, sizeof(zero), &zero);
  const float unit_exposure[2] = {1.0f, 0.0f};
  exposure_block_ = make_buffer(sizeof(unit_exposure), unit_exposure);
  check_gl_errors("FrameRenderer setup");
}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::set_body(const Body& body, std::optional<AtmosphereModel> atmosphere,
                             std::unique_ptr<AtmosphereTechnique> technique) {
  body_ = body;
  atmosphere_ = std::move(atmosphere);
  technique_ = std::move(technique);

  terrain_.reset();  // the old body's tiles go before the new body's come
  terrain_ = std::make_unique<TerrainRenderer>(body, terrain_options_);
#ifdef __GLIBC__
  // The old body's tiles and tables were hundreds of allocations freed at
  // once; hand the free pages back to the system rather than keep them
  // resident for a body that may never come back.
  malloc_trim(0);
#endif

  shadow_field_ = std::make_unique<SunShadowField>();
  shadow_uploaded_ = 0;
  if (atmosphere_) set_atmosphere(*atmosphere_);
  check_gl_errors("FrameRenderer::set_body");
}

void FrameRenderer::set_atmosphere(const AtmosphereModel& atmosphere) {
  if (!atmosphere_) throw std::logic_error("set_atmosphere: the body is drawn without air");
  // The frame's own block (the terrain's lighting reads it) and the technique's.
  atmosphere_ = atmosphere;
  AtmosphereBlock block = make_atmosphere_block(atmosphere);
  glNamedBufferSubData(atmosphere_block_.id(), 0, sizeof(block), &block);
  if (technique_) technique_->update(atmosphere);
}

std::unique_ptr<AtmosphereTechnique> FrameRenderer::swap_technique(
    std::unique_ptr<AtmosphereTechnique> technique) {
  std::swap(technique, technique_);
  return technique;
}

void FrameRenderer::set_fade(AtmosphereTechnique* previous, double weight) {
  fade_from_ = weight > 0.0 ? previous : nullptr;
  fade_weight_ = std::clamp(weight, 0.0, 1.0);
}

void FrameRenderer::set_antialiasing(int samples) {
  GLint most = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &most);
  if (samples < 1 || samples > most) {
    throw SystemError(fmt::format("anti-aliasing: {} samples a pixel asked for; this GL gives 1 to {}",
                                  samples, most));
  }
  samples_ = samples;
  surface_ms_fbo_ = Framebuffer();
  surface_ms_ = Texture();
  ground_below_ms_ = Texture();
  depth_ms_ = Texture();
  if (samples_ == 1) return;
  // Half floats: the samples are resolved straight away, and a surface's
  // radiance (at most a few units) keeps 11 bits, far below what the tone
  // map shows. At 1280x720 on llvmpipe (`planet bench
  // --benchmark_filter=TerrainFrame`) the surfaces from 400 km took 90 ms
  // against 125 with RGBA32F (from 2 m, 400 against 391).
  surface_ms_ = make_texture_2d_multisample(GL_RGBA16F, samples_, width_, height_);
  // Half floats keep a depth of 2.5 km below the datum to 2 m.
  ground_below_ms_ = make_texture_2d_multisample(GL_R16F, samples_, width_, height_);
  depth_ms_ = make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, samples_, width_, height_);
  surface_ms_fbo_ = make_framebuffer({surface_ms_.id(), ground_below_ms_.id()}, depth_ms_.id());
  if (!resolve_program_.id()) {
    resolve_program_ =
        Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/surface_resolve.frag");
    edges_program_ =
        Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/surface_edges.frag");
  }
  check_gl_errors("FrameRenderer::set_antialiasing");
}

void FrameRenderer::set_stars(bool on) {
  stars_on_ = on;
  if (on && !stars_) stars_ = std::make_unique<StarField>(bright_stars());
}

double FrameRenderer::last_exposure() const {
  if (!exposure_measured_) return exposure_;
  float measured[2] = {0, 0};
  DriverWait wait("reading the frame's exposure back");
  glGetNamedBufferSubData(exposure_block_.id(), 0, sizeof(measured), measured);
  return measured[0];
}

void FrameRenderer::draw_stars(const Camera& camera, double exposure) {
  timer_.begin("stars");
  const bool sky = atmosphere_ && technique_;
  StarView view;
  view.body_from_icrf = body_from_icrf_;
  view.has_atmosphere = sky;
  if (sky) {
    // Radiance in W m^-2 sr^-1 nm^-1 under an atmosphere: the sun at 1 AU
    // at the model's wavelengths (whatever the body's distance; the stars
    // do not change with it).
    for (int c = 0; c < 3; ++c) {
      view.sun_at_1au[c] = float(solar_irradiance_astm_g173(atmosphere_->wavelengths_nm[c]));
    }
    view.atmo_scale = atmosphere_scale(body_.shape, atmosphere_->bottom_radius);
    view.scale = technique_->writes_display_values() ? float(exposure) : 1.0f;
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, atmosphere_block_.id());
  }
  const GLuint target = sky ? hdr_fbo_.id() : surface_fbo_.id();
  stars_->draw(target, width_, height_, depth_.id(), camera, view);
  timer_.end();
}

void FrameRenderer::measure_exposure() {
  timer_.begin("exposure");
  if (!exposure_program_.id()) {
    exposure_program_ = Program::compute("render/shaders/auto_exposure.comp");
  }
  glUseProgram(exposure_program_.id());
  glBindTextureUnit(0, radiance().id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, exposure_block_.id());
  glUniform2i(exposure_program_.uniform("u_size"), width_, height_);
  // A middle grey; a cap far above any lit ground or sky (the sun's disc
  // is 10^4 and more); from 1/10 to 10^4, the dark-adapted eye's: there a
  // star of magnitude 3 shows at about display white.
  glUniform1f(exposure_program_.uniform("u_key"), 0.18f);
  glUniform1f(exposure_program_.uniform("u_cap"), 1.0f);
  glUniform2f(exposure_program_.uniform("u_bounds"), 0.1f, 1e4f);
  glDispatchCompute(1, 1, 1);
  // The tone map reads the exposure from the buffer.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  timer_.end();
}

void FrameRenderer::draw_surfaces(const Camera& camera, const glm::dvec3& sun_dir_body,
                                  const AtmosphereTechnique* technique) {
  const float black[4] = {0, 0, 0, 0};
  const GLuint target = samples_ > 1 ? surface_ms_fbo_.id() : surface_draw_fbo_.id();
  begin_reversed_z(target, width_, height_, black);
  glClearNamedFramebufferfv(target, GL_COLOR, 1, black);
  TerrainLighting lighting;
  lighting.sun_dir_body = sun_dir_body;
  lighting.has_atmosphere = atmosphere_.has_value();
  if (atmosphere_) {
    lighting.atmo_scale = atmosphere_scale(body_.shape, atmosphere_->bottom_radius);
    lighting.solar_irradiance = glm::vec3(atmosphere_->solar_irradiance);
    if (technique) lighting.sky_irradiance = technique->ground_irradiance();
    lighting.sky_light = surface_sky_light_;
    lighting.sun_angular_radius = atmosphere_->sun_angular_radius;
  }
  lighting.shadows = terrain_shadows_;
  // Bound even for an airless body (then all zero): the block is declared.
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, atmosphere_block_.id());
  terrain_stats_ = terrain_->draw(camera, width_, height_, lighting);
  glDisable(GL_DEPTH_TEST);
}

void FrameRenderer::resolve_surfaces(const char* pass) {
  if (samples_ == 1) return;
  // One surface per pixel for the passes that follow, its depth written
  // whatever it is.
  timer_.begin(pass);
  tonemap_pass_.begin(surface_draw_fbo_.id(), width_, height_, resolve_program_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glBindTextureUnit(0, surface_ms_.id());
  glBindTextureUnit(1, depth_ms_.id());
  glBindTextureUnit(2, ground_below_ms_.id());
  glUniform1i(resolve_program_.uniform("u_samples"), samples_);
  tonemap_pass_.draw();
  glDisable(GL_DEPTH_TEST);
  timer_.end();
}

void FrameRenderer::blend_surface_edges(GLuint target, const char* pass) {
  if (samples_ == 1) return;
  timer_.begin(pass);
  // The pass reads open pixels and writes only partly covered ones.
  glTextureBarrier();
  tonemap_pass_.begin(target, width_, height_, edges_program_);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glBindTextureUnit(0, radiance().id());
  glBindTextureUnit(1, surface_.id());
  glUniform1i(edges_program_.uniform("u_open_is_black"), target == surface_fbo_.id() ? 1 : 0);
  tonemap_pass_.draw();
  glDisable(GL_BLEND);
  timer_.end();
}

SkyTerrainShadow FrameRenderer::terrain_shadow(const glm::dvec3& camera_atmo,
                                               const glm::dvec3& sun_atmo,
                                               const glm::dvec3& atmo_scale) {
  SkyTerrainShadow shadow;
  const HeightRange relief = terrain_->surface().heights().range();
  const double bottom = atmosphere_->bottom_radius;
  const double altitude = glm::length(camera_atmo) - bottom;
  const double fade = std::clamp((kTerrainShadowTop - altitude) / 20e3, 0.0, 1.0);
  if (!terrain_shadows_ || relief.max <= relief.min || fade <= 0.0) return shadow;
  // The field on the CPU and its upload, timed together.
  const auto began = std::chrono::steady_clock::now();
  shadow_field_->update(terrain_->surface(), atmo_scale, bottom, camera_atmo, sun_atmo);
  const SunShadowField& field = *shadow_field_;
  if (shadow_uploaded_ == field.version()) {
    timer_.reuse("terrain_shadow");
  } else {
    const int n = field.patch().size;
    if (!shadow_texture_.id()) {
      shadow_texture_ = make_texture_2d(GL_R32F, n, n);
      glTextureParameteri(shadow_texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTextureParameteri(shadow_texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glTextureSubImage2D(shadow_texture_.id(), 0, 0, 0, n, n, GL_RED, GL_FLOAT,
                        field.shadow().data());
    shadow_uploaded_ = field.version();
    timer_.cpu("terrain_shadow", std::chrono::duration<double, std::milli>(
                                     std::chrono::steady_clock::now() - began)
                                     .count());
  }
  // A sun high enough leaves no shadow in the patch: nothing to draw.
  if (!std::isfinite(field.highest_shadow())) return shadow;
  const ShadowPatch& patch = field.patch();
  shadow.texture = shadow_texture_.id();
  shadow.highest = float(field.highest_shadow());
  shadow.up = glm::vec3(patch.up);
  shadow.east = glm::vec3(patch.east);
  shadow.north = glm::vec3(patch.north);
  shadow.bottom_radius = float(patch.bottom_radius);
  shadow.half_side = float(patch.half_side);
  shadow.strength = float(fade * fade * (3.0 - 2.0 * fade));
  shadow.version = field.version();
  return shadow;
}

void FrameRenderer::draw_atmosphere(const Camera& camera, const glm::dvec3& sun_dir_body,
                                    double exposure, AtmosphereTechnique& technique) {
  glm::dvec3 scale = atmosphere_scale(body_.shape, atmosphere_->bottom_radius);
  SkyFrame sky;
  sky.width = width_;
  sky.height = height_;
  sky.camera_atmo = scale * camera.pos_body;
  sky.atmo_ray_from_ndc =
      glm::mat3(atmo_ray_from_ndc(scale, camera, double(width_) / double(height_)));
  sky.sun_dir_atmo = glm::vec3(glm::normalize(scale * sun_dir_body));
  sky.near = float(camera.near);
  // A lower bound of every distance the technique meets in front of a
  // surface: the nearest drawn tile, less the depth of the lowest ground
  // below the ellipsoid (a ray may cross the bottom sphere, where the
  // technique's air ends, up to that much before it meets a tile in a
  // hollow), in atmosphere space, which shrinks no distance by more than
  // its smallest scale.
  const double lowest = std::min(0.0, terrain_->surface().heights().range().min);
  sky.atmo_scale_min = float(std::min({scale.x, scale.y, scale.z}));
  sky.nearest_surface =
      view_pruning_ ? float(std::max(terrain_stats_.nearest_m + lowest, 0.0) * sky.atmo_scale_min)
                    : 0.0f;
  sky.view_pruning = view_pruning_;
  if (technique.takes_terrain_shadow()) {
    sky.terrain_shadow = terrain_shadow(sky.camera_atmo, glm::dvec3(sky.sun_dir_atmo), scale);
  }
  sky.exposure = float(exposure);
  sky.depth_texture = depth_.id();
  sky.surface_texture = surface_.id();
  sky.ground_below_texture = ground_below_.id();
  const HeightRange heights = terrain_->surface().heights().range();
  const double scale_max = std::max({scale.x, scale.y, scale.z});
  sky.ground_heights = glm::vec2(float(std::min(0.0, heights.min) * scale_max),
                                 float(std::max(0.0, heights.max) * scale_max));
  sky.target_framebuffer = hdr_fbo_.id();
  const GLint zero = 0;
  glClearNamedFramebufferiv(hdr_fbo_.id(), GL_STENCIL, 0, &zero);
  technique.render(sky, timer_);
  blend_surface_edges(hdr_fbo_.id(), &technique == technique_.get() ? "antialias" : "fade:antialias");
}

FrameStats FrameRenderer::render(const Camera& camera, const glm::dvec3& sun_dir_body,
                                 double exposure) {
  // Before the surface timer starts: waiting is not drawing.
  if (terrain_wait_s_ > 0) terrain_->wait_until_complete(camera, width_, height_, terrain_wait_s_);
  const bool sky = atmosphere_ && technique_;
  AtmosphereTechnique* fading =
      sky && fade_from_ &&
              fade_from_->writes_display_values() == technique_->writes_display_values()
          ? fade_from_
          : nullptr;
  // The technique's model-wide tables first: the ground's sky light is one.
  if (sky) technique_->prepare(timer_);
  if (fading) {
    // The previous technique's frame, whole, into the fade texture.
    fading->prepare(timer_);
    timer_.begin("fade:surface");
    draw_surfaces(camera, sun_dir_body, fading);
    timer_.end();
    resolve_surfaces("fade:resolve");
    draw_atmosphere(camera, sun_dir_body, exposure, *fading);
    if (!fade_.id()) fade_ = make_texture_2d(GL_RGBA32F, width_, height_);
    glCopyImageSubData(hdr_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, fade_.id(), GL_TEXTURE_2D, 0, 0, 0,
                       0, width_, height_, 1);
  }
  timer_.begin("surface");
  draw_surfaces(camera, sun_dir_body, sky ? technique_.get() : nullptr);
  timer_.end();
  resolve_surfaces("resolve");

  if (sky) {
    draw_atmosphere(camera, sun_dir_body, exposure, *technique_);
  } else {
    // Airless, the surfaces are the image: no atmosphere pass, not even a
    // copy.
    blend_surface_edges(surface_fbo_.id(), "antialias");
  }

  if (fading) {
    timer_.begin("fade");
    if (!fade_program_.id()) {
      fade_program_ = Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/fade.frag");
    }
    tonemap_pass_.begin(hdr_fbo_.id(), width_, height_, fade_program_);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glBindTextureUnit(0, fade_.id());
    glUniform1f(fade_program_.uniform("u_weight"), float(fade_weight_));
    tonemap_pass_.draw();
    glDisable(GL_BLEND);
    timer_.end();
  }

  if (stars_on_) draw_stars(camera, exposure);
  exposure_ = exposure;
  const bool display_values = sky && technique_->writes_display_values();
  exposure_measured_ = auto_exposure_ && !display_values;
  if (exposure_measured_) measure_exposure();

  const bool glare = glare_ && !display_values;
  if (glare) draw_glare();

  timer_.begin("tonemap");
  tonemap_pass_.begin(ldr_fbo_.id(), width_, height_, tonemap_program_);
  glBindTextureUnit(0, radiance().id());
  glUniform1f(tonemap_program_.uniform("u_glare_per_octave"),
              glare ? float(kGlarePerOctave) : 0.0f);
  if (glare) {
    glBindTextureUnit(1, glare_up_[0].id());
    glUniform1i(tonemap_program_.uniform("u_glare_octaves"), int(glare_up_.size()));
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, exposure_block_.id());
  glUniform1f(tonemap_program_.uniform("u_exposure"), float(exposure));
  glUniform1i(tonemap_program_.uniform("u_auto_exposure"),
              auto_exposure_ && !display_values ? 1 : 0);
  glUniform1i(tonemap_program_.uniform("u_display_values"), display_values ? 1 : 0);
  tonemap_pass_.draw();
  timer_.end();

  if (smooth_edges_) {
    timer_.begin("smooth_edges");
    if (!ldr_unsmoothed_.id()) {
      ldr_unsmoothed_ = make_texture_2d(GL_RGBA8, width_, height_);
      smooth_edges_program_ =
          Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/smooth_edges.frag");
    }
    glCopyImageSubData(ldr_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ldr_unsmoothed_.id(), GL_TEXTURE_2D, 0,
                       0, 0, 0, width_, height_, 1);
    tonemap_pass_.begin(ldr_fbo_.id(), width_, height_, smooth_edges_program_);
    glBindTextureUnit(0, ldr_unsmoothed_.id());
    tonemap_pass_.draw();
    timer_.end();
  }

  FrameStats stats;
  stats.passes = timer_.collect();
  check_gl_errors("FrameRenderer::render");
  return stats;
}

// The glare's light, one level per octave of angle: the radiance halved
// again and again (each level keeps the image's energy), then summed back
// up with each coarser level spread one octave wider. Equal shares per
// octave make the 1 / theta^2 of the glare equation (kGlarePerOctave); the
// tone map takes the share from the pixel and adds the sum.
void FrameRenderer::draw_glare() {
  timer_.begin("glare");
  if (glare_down_.empty()) {
    glare_down_program_ =
        Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/glare_down.frag");
    glare_up_program_ =
        Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/glare_up.frag");
    int w = width_, h = height_;
    for (int level = 0; level < kGlareOctaves && (w > 1 || h > 1); ++level) {
      w = std::max(1, (w + 1) / 2);
      h = std::max(1, (h + 1) / 2);
      glare_down_.push_back(make_texture_2d(GL_RGBA16F, w, h));
      glare_up_.push_back(make_texture_2d(GL_RGBA16F, w, h));
      glare_down_fbo_.push_back(make_framebuffer(glare_down_.back().id(), 0));
      glare_up_fbo_.push_back(make_framebuffer(glare_up_.back().id(), 0));
    }
  }
  auto size = [](const Texture& t) {
    GLint w = 0, h = 0;
    glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_HEIGHT, &h);
    return glm::ivec2(w, h);
  };
  const size_t levels = glare_down_.size();
  for (size_t i = 0; i < levels; ++i) {
    glm::ivec2 s = size(glare_down_[i]);
    tonemap_pass_.begin(glare_down_fbo_[i].id(), s.x, s.y, glare_down_program_);
    glBindTextureUnit(0, i == 0 ? radiance().id() : glare_down_[i - 1].id());
    tonemap_pass_.draw();
  }
  // The coarsest level is its own sum.
  glm::ivec2 last = size(glare_down_[levels - 1]);
  glCopyImageSubData(glare_down_[levels - 1].id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                     glare_up_[levels - 1].id(), GL_TEXTURE_2D, 0, 0, 0, 0, last.x, last.y, 1);
  for (size_t i = levels - 1; i-- > 0;) {
    glm::ivec2 s = size(glare_up_[i]);
    tonemap_pass_.begin(glare_up_fbo_[i].id(), s.x, s.y, glare_up_program_);
    glBindTextureUnit(0, glare_down_[i].id());
    glBindTextureUnit(1, glare_up_[i + 1].id());
    tonemap_pass_.draw();
  }
  timer_.end();
}

const Texture& FrameRenderer::radiance() const {
  return atmosphere_ && technique_ ? hdr_ : surface_;
}

std::vector<float> FrameRenderer::read_hdr() const {
  return read_texture_rgba32f(radiance().id(), width_, height_);
}

std::vector<float> FrameRenderer::read_distance(const Camera& camera) const {
  std::vector<float> depth(size_t(width_) * size_t(height_));
  {
    DriverWait wait("reading the frame's depth back");
    glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(depth.size() * sizeof(float)), depth.data());
  }
  const glm::dmat3 ray_from_ndc = view_ray_from_ndc(camera.vertical_fov, double(width_) / height_);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      float& d = depth[size_t(y) * size_t(width_) + size_t(x)];
      if (d <= 0.0f) {
        d = std::numeric_limits<float>::infinity();
        continue;
      }
      // Reversed Z: view depth = near / depth, times the ray's length per
      // unit of view depth at the pixel's centre.
      glm::dvec2 ndc(2.0 * (x + 0.5) / width_ - 1.0, 2.0 * (y + 0.5) / height_ - 1.0);
      d = float(camera.near / double(d) * glm::length(ray_from_ndc * glm::dvec3(ndc, 1.0)));
    }
  }
  return depth;
}

std::vector<uint8_t> FrameRenderer::read_ldr() const {
  std::vector<uint8_t> pixels(size_t(width_) * size_t(height_) * 4);
  DriverWait wait("reading the frame's image back");
  glGetTextureImage(ldr_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
  return pixels;
}

}  // namespace planet
