#include "render/frame.h"

#include "atmosphere/atmosphere_inputs.h"
#include "atmosphere/atmosphere_space.h"
#include "atmosphere/gpu/atmosphere_block.h"
#include "clouds/cloud_model.h"
#include "gl/context.h"
#include "gl/driver_watch.h"
#include "render/glare.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace planet {

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
  clouds_.reset();
  if (atmosphere_) {
    if (std::optional<CloudModel> clouds = load_clouds(body)) {
      clouds_ = to_shared(*clouds, atmosphere_->bottom_radius);
    }
  }

  terrain_.reset();  // the old body's tiles go before the new body's come
  terrain_ = std::make_unique<TerrainRenderer>(body, options_.terrain);
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

namespace {

// The exposure of a frame's radiance from its mean luminance, into `block`
// (auto_exposure.comp), where the tone map reads it.
void measure_exposure(const Program& program, GLuint radiance, GLuint block, int width,
                      int height) {
  glUseProgram(program.id());
  glBindTextureUnit(0, radiance);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, block);
  glUniform2i(program.uniform("u_size"), width, height);
  // A middle grey; a cap far above any lit ground or sky (the sun's disc
  // is 10^4 and more); from 1/10 to 10^4, the dark-adapted eye's: there a
  // star of magnitude 3 shows at about display white.
  glUniform1f(program.uniform("u_key"), 0.18f);
  glUniform1f(program.uniform("u_cap"), 1.0f);
  glUniform2f(program.uniform("u_bounds"), 0.1f, 1e4f);
  glDispatchCompute(1, 1, 1);
  // The tone map reads the exposure from the buffer.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void copy_image(const Texture& from, const Texture& to, int width, int height) {
  glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, 0, 0, 0, to.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                     width, height, 1);
}

// The share of the terrain's shadow in the air a camera `altitude` above
// the bottom sphere sees: all of it below kTerrainShadowTop - 20 km, none
// above kTerrainShadowTop.
double terrain_shadow_fade(double altitude) {
  return std::clamp((kTerrainShadowTop - altitude) / 20e3, 0.0, 1.0);
}

}  // namespace

// What one render() draws: its arguments, and what follows from them.
struct FrameRenderer::Frame {
  const Camera& camera;
  glm::dvec3 sun_dir_body;
  double exposure;
  bool sky = false;  // an atmosphere, drawn by a technique
  // The previous technique while a switch fades, if its values are of the
  // same kind as the technique's (radiance or display values).
  AtmosphereTechnique* fading = nullptr;
  bool display_values = false;  // the technique's target holds display values
  // With a sky: atmosphere space (atmosphere_space.h).
  glm::dvec3 atmo_scale{1.0}, camera_atmo{0.0};
  glm::vec3 sun_dir_atmo{0, 0, 1};
  // The Moon's radius for this frame's passes: 0 where it covers no part
  // of the sun from anywhere the frame draws (eclipsing_moon_radius).
  double moon_radius = 0;
};

double FrameRenderer::eclipsing_moon_radius(const Frame& f) const {
  if (moon_radius_ <= 0.0) return 0.0;
  // Every point the frame draws (the camera, the air, the ground) lies
  // within `reach` of the body's centre: from there the Moon stands at
  // most asin(reach / d) from where the centre sees it, and the sun
  // reach / 1 AU. Near the Moon, keep it.
  const double moon_distance = glm::length(moon_pos_body_);
  double top = body_.shape.equatorial_radius;
  if (atmosphere_) top *= atmosphere_->top_radius / atmosphere_->bottom_radius;
  const double reach = std::max(glm::length(f.camera.pos_body), top);
  if (reach >= 0.5 * moon_distance) return moon_radius_;
  const double sun_radius = atmosphere_ ? atmosphere_->sun_angular_radius : 0.0;
  const double cos_separation = glm::dot(moon_pos_body_ / moon_distance, f.sun_dir_body);
  const double separation = std::acos(std::clamp(cos_separation, -1.0, 1.0));
  const double within = sun_radius + std::asin(moon_radius_ / (moon_distance - reach)) +
                        std::asin(reach / moon_distance) + reach / 1.495978707e11 + 1e-3;
  return separation <= within ? moon_radius_ : 0.0;
}

void FrameRenderer::set_options(const FrameOptions& options) {
  SurfaceAntialiasing::check_samples(options.antialiasing);
  if (options.antialiasing != options_.antialiasing) {
    multisampled_.reset();
    if (options.antialiasing > 1) {
      multisampled_ = std::make_unique<SurfaceAntialiasing>(options.antialiasing, width_, height_);
    }
  }
  options_ = options;
  if (options_.stars && !stars_) stars_ = std::make_unique<StarField>(bright_stars());
  timer_.set_synchronous(options_.synchronous_timing);
}

double FrameRenderer::last_exposure() const {
  if (!exposure_measured_) return exposure_;
  float measured[2] = {0, 0};
  DriverWait wait("reading the frame's exposure back");
  glGetNamedBufferSubData(exposure_block_.id(), 0, sizeof(measured), measured);
  return measured[0];
}

FrameStats FrameRenderer::render(const Camera& camera, const glm::dvec3& sun_dir_body,
                                 double exposure) {
  // Before the first pass: waiting is not drawing.
  if (options_.terrain_wait_s > 0) {
    terrain_->wait_until_complete(camera, width_, height_, options_.terrain_wait_s);
  }
  Frame f{camera, sun_dir_body, exposure};
  f.sky = atmosphere_ && technique_;
  if (f.sky) {
    if (fade_from_ && fade_from_->writes_display_values() == technique_->writes_display_values()) {
      f.fading = fade_from_;
    }
    f.display_values = technique_->writes_display_values();
    f.atmo_scale = atmosphere_scale(body_.shape, atmosphere_->bottom_radius);
    f.camera_atmo = f.atmo_scale * camera.pos_body;
    f.sun_dir_atmo = glm::vec3(glm::normalize(f.atmo_scale * sun_dir_body));
  }
  f.moon_radius = eclipsing_moon_radius(f);
  exposure_ = exposure;
  exposure_measured_ = options_.auto_exposure && !f.display_values;
  graph_.run(passes(f), timer_);
  FrameStats stats;
  stats.passes = timer_.collect();
  check_gl_errors("FrameRenderer::render");
  return stats;
}

namespace {

// A pass of the frame; `needed` empty: every frame needs it.
Pass frame_pass(std::string name, std::vector<std::string> reads, std::function<bool()> needed,
                std::function<void()> run) {
  Pass p;
  p.name = std::move(name);
  p.reads = std::move(reads);
  p.needed = std::move(needed);
  p.run = std::move(run);
  return p;
}

// A pass that times itself: a technique's, which times its own passes, or
// one that runs on the CPU.
Pass self_timed_pass(std::string name, std::vector<std::string> reads, std::function<bool()> needed,
                     std::function<void()> run) {
  Pass p = frame_pass(std::move(name), std::move(reads), std::move(needed), std::move(run));
  p.times_itself = true;
  return p;
}

}  // namespace

std::vector<Pass> FrameRenderer::passes(const Frame& f) {
  std::vector<Pass> out;
  // The technique's model-wide tables first: the ground's sky light is one.
  out.push_back(self_timed_pass(
      "atmosphere_tables", {}, [&f] { return f.sky; }, [this] { technique_->prepare(timer_); }));
  // The previous technique's frame, whole, kept in the fade texture: a
  // graph of its own, whose passes are timed each.
  out.push_back(self_timed_pass(
      "fade:frame", {}, [&f] { return f.fading != nullptr; },
      [this, &f] {
        std::vector<Pass> fade = radiance_passes(f, f.fading, "fade:");
        fade.push_back(frame_pass("fade:keep", {"fade:antialias"}, {}, [this] {
          if (!fade_.id()) fade_ = make_texture_2d(GL_RGBA32F, width_, height_);
          copy_image(hdr_, fade_, width_, height_);
        }));
        fade_graph_.run(std::move(fade), timer_);
      }));
  for (Pass& pass : radiance_passes(f, technique_.get(), "")) out.push_back(std::move(pass));
  for (Pass& pass : image_passes(f)) out.push_back(std::move(pass));
  return out;
}

// The frame's radiance drawn by `technique` (none: an airless body's
// surfaces alone), each pass's name after `prefix`; the fade's
// (prefix "fade:") has its technique's tables too.
std::vector<Pass> FrameRenderer::radiance_passes(const Frame& f, AtmosphereTechnique* technique,
                                                 const std::string& prefix) {
  auto multisampled = [this] { return multisampled_ != nullptr; };
  std::vector<Pass> out;
  if (!prefix.empty()) {
    out.push_back(self_timed_pass(prefix + "atmosphere_tables", {}, {},
                                  [this, technique] { technique->prepare(timer_); }));
  }
  out.push_back(
      frame_pass(prefix + "surface", {prefix + "atmosphere_tables"}, {},
                 [this, &f, technique] { draw_surfaces(f, f.sky ? technique : nullptr); }));
  // One surface per pixel for the passes that follow, its depth written
  // whatever it is.
  out.push_back(frame_pass(prefix + "resolve", {prefix + "surface"}, multisampled, [this] {
    multisampled_->resolve(tonemap_pass_, surface_draw_fbo_.id());
  }));
  // On the CPU: it times itself, and says when its field was reused.
  out.push_back(self_timed_pass(
      prefix + "terrain_shadow", {},
      [this, &f, technique] { return terrain_shadow_needed(f, technique); },
      [this, &f, name = prefix + "terrain_shadow"] { update_terrain_shadow(f, name); }));
  // Airless, the surfaces are the image: no atmosphere pass, not even a
  // copy.
  out.push_back(self_timed_pass(
      prefix + "atmosphere", {prefix + "resolve", prefix + "terrain_shadow"},
      [&f] { return f.sky; }, [this, &f, technique] { draw_atmosphere(f, *technique); }));
  // The clouds over the sky and the ground, in radiance.
  out.push_back(frame_pass(
      prefix + "clouds", {prefix + "atmosphere"}, [this, &f] { return clouds_drawn(f); },
      [this, &f, technique] { draw_clouds(f, *technique); }));
  // The partly covered pixels of the radiance take the rest from the open
  // ones beside them.
  out.push_back(frame_pass(prefix + "antialias", {prefix + "atmosphere"}, multisampled, [this, &f] {
    multisampled_->blend_edges(tonemap_pass_, f.sky ? hdr_fbo_.id() : surface_fbo_.id(),
                               radiance().id(), surface_.id(), !f.sky);
  }));
  return out;
}

// After the radiance: the fade's image laid over it, the stars, the
// exposure, the glare, the tone map and the smoothing of its edges.
std::vector<Pass> FrameRenderer::image_passes(const Frame& f) {
  const bool glare = options_.glare && !f.display_values;
  std::vector<Pass> out;
  out.push_back(frame_pass(
      "fade", {"fade:frame", "antialias"}, [&f] { return f.fading != nullptr; },
      [this] {
        if (!fade_program_.id()) {
          fade_program_ =
              Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/fade.frag");
        }
        tonemap_pass_.begin(hdr_fbo_.id(), width_, height_, fade_program_);
        glDisable(GL_STENCIL_TEST);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glBindTextureUnit(0, fade_.id());
        glUniform1f(fade_program_.uniform("u_weight"), float(fade_weight_));
        tonemap_pass_.draw();
        glDisable(GL_BLEND);
      }));
  out.push_back(frame_pass(
      "stars", {"fade"}, [this] { return options_.stars; }, [this, &f] { draw_stars(f); }));
  out.push_back(frame_pass(
      "exposure", {"stars"}, [this] { return exposure_measured_; },
      [this] {
        if (!exposure_program_.id()) {
          exposure_program_ = Program::compute("render/shaders/auto_exposure.comp");
        }
        measure_exposure(exposure_program_, radiance().id(), exposure_block_.id(), width_, height_);
      }));
  out.push_back(frame_pass(
      "glare", {"stars"}, [glare] { return glare; },
      [this] {
        if (!glare_) glare_ = std::make_unique<GlarePyramid>(width_, height_);
        glare_->draw(tonemap_pass_, radiance().id());
      }));
  out.push_back(frame_pass("tonemap", {"exposure", "glare"}, {}, [this, &f] { tonemap(f); }));
  out.push_back(frame_pass(
      "smooth_edges", {"tonemap"}, [this] { return options_.smooth_edges; },
      [this] {
        if (!ldr_unsmoothed_.id()) {
          ldr_unsmoothed_ = make_texture_2d(GL_RGBA8, width_, height_);
          smooth_edges_program_ =
              Program::graphics("gl/shaders/fullscreen.vert", "render/shaders/smooth_edges.frag");
        }
        copy_image(ldr_, ldr_unsmoothed_, width_, height_);
        tonemap_pass_.begin(ldr_fbo_.id(), width_, height_, smooth_edges_program_);
        glBindTextureUnit(0, ldr_unsmoothed_.id());
        tonemap_pass_.draw();
      }));
  return out;
}

void FrameRenderer::draw_surfaces(const Frame& f, const AtmosphereTechnique* technique) {
  const float black[4] = {0, 0, 0, 0};
  // With anti-aliasing, the coverage's samples first, then the lit
  // surfaces once a pixel (surface_antialiasing.h), the same tiles both.
  const GLuint coverage = multisampled_ ? multisampled_->coverage_framebuffer() : 0;
  if (coverage != 0) begin_reversed_z(coverage, width_, height_, black);
  const GLuint target = multisampled_ ? multisampled_->framebuffer() : surface_draw_fbo_.id();
  begin_reversed_z(target, width_, height_, black);
  glClearNamedFramebufferfv(target, GL_COLOR, 1, black);
  TerrainLighting lighting;
  lighting.sun_dir_body = f.sun_dir_body;
  lighting.has_atmosphere = atmosphere_.has_value();
  if (atmosphere_) {
    lighting.atmo_scale = atmosphere_scale(body_.shape, atmosphere_->bottom_radius);
    lighting.solar_irradiance = glm::vec3(atmosphere_->solar_irradiance);
    if (technique) lighting.sky_irradiance = technique->ground_irradiance();
    lighting.sky_light = options_.surface_sky_light;
    lighting.sun_angular_radius = atmosphere_->sun_angular_radius;
  }
  lighting.shadows = options_.terrain_shadows;
  lighting.moon_pos_body = moon_pos_body_;
  lighting.moon_radius = f.moon_radius;
  // Bound even for an airless body (then all zero): the block is declared.
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, atmosphere_block_.id());
  terrain_stats_ = terrain_->draw(f.camera, width_, height_, lighting, coverage);
  glDisable(GL_DEPTH_TEST);
}

bool FrameRenderer::terrain_shadow_needed(const Frame& f,
                                          const AtmosphereTechnique* technique) const {
  if (!f.sky || !technique || !technique->takes_terrain_shadow()) return false;
  const HeightRange relief = terrain_->surface().heights().range();
  const double altitude = glm::length(f.camera_atmo) - atmosphere_->bottom_radius;
  return options_.terrain_shadows && relief.max > relief.min && terrain_shadow_fade(altitude) > 0.0;
}

void FrameRenderer::update_terrain_shadow(const Frame& f, const std::string& pass) {
  // The field on the CPU and its upload, timed together.
  const auto began = std::chrono::steady_clock::now();
  shadow_field_->update(terrain_->surface(), f.atmo_scale, atmosphere_->bottom_radius,
                        f.camera_atmo, glm::dvec3(f.sun_dir_atmo));
  const SunShadowField& field = *shadow_field_;
  if (shadow_uploaded_ == field.version()) {
    timer_.reuse(pass);
    return;
  }
  const int n = field.patch().size;
  if (!shadow_texture_.id()) {
    shadow_texture_ = make_texture_2d(GL_R32F, n, n);
    glTextureParameteri(shadow_texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(shadow_texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage2D(shadow_texture_.id(), 0, 0, 0, n, n, GL_RED, GL_FLOAT, field.shadow().data());
  shadow_uploaded_ = field.version();
  timer_.cpu(
      pass,
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count());
}

SkyTerrainShadow FrameRenderer::terrain_shadow(const Frame& f) const {
  SkyTerrainShadow shadow;
  const SunShadowField& field = *shadow_field_;
  // A sun high enough leaves no shadow in the patch: nothing to draw.
  if (!std::isfinite(field.highest_shadow())) return shadow;
  const double fade = terrain_shadow_fade(glm::length(f.camera_atmo) - atmosphere_->bottom_radius);
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

void FrameRenderer::draw_atmosphere(const Frame& f, AtmosphereTechnique& technique) {
  const glm::dvec3 scale = f.atmo_scale;
  SkyFrame sky;
  sky.width = width_;
  sky.height = height_;
  sky.camera_atmo = f.camera_atmo;
  sky.atmo_ray_from_ndc =
      glm::mat3(atmo_ray_from_ndc(scale, f.camera, double(width_) / double(height_)));
  sky.sun_dir_atmo = f.sun_dir_atmo;
  // Carried into atmosphere space as every point is (lab/scene.cpp's
  // reference_view does the same for the ground truth).
  sky.moon_centre_atmo = glm::vec3(scale * moon_pos_body_);
  sky.moon_radius = float(scale.x * f.moon_radius);
  sky.near = float(f.camera.near);
  // A lower bound of every distance the technique meets in front of a
  // surface: the nearest drawn tile, less the depth of the lowest ground
  // below the ellipsoid (a ray may cross the bottom sphere, where the
  // technique's air ends, up to that much before it meets a tile in a
  // hollow), in atmosphere space, which shrinks no distance by more than
  // its smallest scale.
  const HeightRange heights = terrain_->surface().heights().range();
  const double lowest = std::min(0.0, heights.min);
  sky.atmo_scale_min = float(std::min({scale.x, scale.y, scale.z}));
  sky.nearest_surface =
      options_.view_pruning
          ? float(std::max(terrain_stats_.nearest_m + lowest, 0.0) * sky.atmo_scale_min)
          : 0.0f;
  sky.view_pruning = options_.view_pruning;
  if (terrain_shadow_needed(f, &technique)) sky.terrain_shadow = terrain_shadow(f);
  sky.exposure = float(f.exposure);
  sky.depth_texture = depth_.id();
  sky.surface_texture = surface_.id();
  sky.ground_below_texture = ground_below_.id();
  const double scale_max = std::max({scale.x, scale.y, scale.z});
  sky.ground_heights = glm::vec2(float(std::min(0.0, heights.min) * scale_max),
                                 float(std::max(0.0, heights.max) * scale_max));
  sky.target_framebuffer = hdr_fbo_.id();
  const GLint zero = 0;
  glClearNamedFramebufferiv(hdr_fbo_.id(), GL_STENCIL, 0, &zero);
  technique.render(sky, timer_);
}

bool FrameRenderer::clouds_drawn(const Frame& f) const {
  return f.sky && !f.display_values && options_.clouds && clouds_.has_value();
}

void FrameRenderer::draw_clouds(const Frame& f, const AtmosphereTechnique& technique) {
  if (!cloud_pass_) cloud_pass_ = std::make_unique<CloudPass>();
  SkyFrame sky;
  sky.width = width_;
  sky.height = height_;
  sky.camera_atmo = f.camera_atmo;
  sky.atmo_ray_from_ndc =
      glm::mat3(atmo_ray_from_ndc(f.atmo_scale, f.camera, double(width_) / double(height_)));
  sky.sun_dir_atmo = f.sun_dir_atmo;
  sky.near = float(f.camera.near);
  sky.depth_texture = depth_.id();
  sky.surface_texture = surface_.id();
  sky.target_framebuffer = hdr_fbo_.id();
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, atmosphere_block_.id());
  glBindTextureUnit(SkyFrame::kGroundBelowUnit, ground_below_.id());
  cloud_pass_->draw(sky, *clouds_, options_.cloud_quality, technique.ground_irradiance());
}

void FrameRenderer::draw_stars(const Frame& f) {
  StarView view;
  view.body_from_icrf = body_from_icrf_;
  view.has_atmosphere = f.sky;
  if (f.sky) {
    // Radiance in W m^-2 sr^-1 nm^-1 under an atmosphere: the sun at 1 AU
    // at the model's wavelengths (whatever the body's distance; the stars
    // do not change with it).
    for (int c = 0; c < 3; ++c) {
      view.sun_at_1au[c] = float(solar_irradiance_astm_g173(atmosphere_->wavelengths_nm[c]));
    }
    view.atmo_scale = f.atmo_scale;
    view.scale = f.display_values ? float(f.exposure) : 1.0f;
    if (clouds_drawn(f)) view.clouds = cloud_pass_->clouds_texture();
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, atmosphere_block_.id());
  }
  const GLuint target = f.sky ? hdr_fbo_.id() : surface_fbo_.id();
  stars_->draw(target, width_, height_, depth_.id(), f.camera, view);
}

void FrameRenderer::tonemap(const Frame& f) {
  const bool glare = options_.glare && !f.display_values;
  tonemap_pass_.begin(ldr_fbo_.id(), width_, height_, tonemap_program_);
  glBindTextureUnit(0, radiance().id());
  glUniform1f(tonemap_program_.uniform("u_glare_per_octave"),
              glare ? float(kGlarePerOctave) : 0.0f);
  if (glare) {
    glBindTextureUnit(1, glare_->sum());
    glUniform1i(tonemap_program_.uniform("u_glare_octaves"), glare_->octaves());
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, exposure_block_.id());
  glUniform1f(tonemap_program_.uniform("u_exposure"), float(f.exposure));
  glUniform1i(tonemap_program_.uniform("u_auto_exposure"), exposure_measured_ ? 1 : 0);
  glUniform1i(tonemap_program_.uniform("u_display_values"), f.display_values ? 1 : 0);
  tonemap_pass_.draw();
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
