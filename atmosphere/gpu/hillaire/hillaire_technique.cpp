#include "atmosphere/gpu/hillaire/hillaire_technique.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "atmosphere/gpu/terrain_shadow.h"
#include "atmosphere/math/hillaire_math.h"
#include "atmosphere/screen_bound.h"
#include "gl/timer.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace planet {

namespace {

constexpr GLuint kGroupSize = 8;  // local_size_x and _y of every compute pass
// After a pass that writes a LUT: later passes sample or write it.
constexpr GLbitfield kLutBarrier =
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;

GLuint groups(int size) { return GLuint((size + int(kGroupSize) - 1) / int(kGroupSize)); }

double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Rows: the horizontal direction toward the sun's azimuth, the one across
// it, and up at the camera. Any horizontal axis serves when the sun stands
// at the zenith (or nadir), where the sky has no azimuth to follow.
glm::dmat3 local_from_atmo(const glm::dvec3& camera, const glm::dvec3& sun) {
  double r = glm::length(camera);
  glm::dvec3 up = r > 0.0 ? camera / r : glm::dvec3(0, 0, 1);
  glm::dvec3 toward_sun = sun - up * glm::dot(up, sun);
  if (glm::length(toward_sun) < 1e-6) {
    glm::dvec3 any = std::abs(up.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    toward_sun = glm::cross(up, any);
  }
  glm::dvec3 x = glm::normalize(toward_sun);
  glm::dvec3 y = glm::cross(up, x);
  return glm::transpose(glm::dmat3(x, y, up));
}

void bind_image(GLuint unit, GLuint texture, GLenum format, bool layered) {
  glBindImageTexture(unit, texture, 0, layered ? GL_TRUE : GL_FALSE, 0, GL_WRITE_ONLY, format);
}

// Pixels a side of sky_march_tiles.comp's tiles, and the buffer binding of
// its list.
constexpr int kMarchTile = 8;
constexpr GLuint kMarchTilesBinding = 4;

// Texture unit of the froxels' shadow loss in the sky pass.
constexpr GLuint kShadowLossUnit = 10;
// Texture units of the space-view LUT's open sky, then its two 3D tables,
// in the sky pass (hillaire_sky.frag).
constexpr GLuint kSpaceOpenSkyUnit = 12;

// The pixels of an NDC rectangle on a w x h target with `margin` to spare
// on each side, clamped to the target: x, y, width, height.
glm::ivec4 pixel_rect(const NdcRect& ndc, int w, int h, int margin) {
  auto pixel = [](double x, int size) { return 0.5 * (x + 1.0) * size; };
  int x0 = std::clamp(int(std::floor(pixel(ndc.min.x, w))) - margin, 0, w);
  int x1 = std::clamp(int(std::ceil(pixel(ndc.max.x, w))) + margin, 0, w);
  int y0 = std::clamp(int(std::floor(pixel(ndc.min.y, h))) - margin, 0, h);
  int y1 = std::clamp(int(std::ceil(pixel(ndc.max.y, h))) + margin, 0, h);
  return glm::ivec4(x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0));
}

// Rounds x to the nearest multiple of step (none when step is 0).
double quantize(double x, double step) { return step > 0.0 ? std::round(x / step) * step : x; }

// One compute pass that fills a whole 2D LUT, one invocation per texel.
void build_lut(const Program& program, const Texture& lut, GLenum format, int width, int height) {
  program.use();
  bind_image(0, lut.id(), format, false);
  glDispatchCompute(groups(width), groups(height), 1);
  glMemoryBarrier(kLutBarrier);
}

}  // namespace

HillaireTechnique::HillaireTechnique(Settings settings)
    : settings_(settings),
      schedule_(settings.schedule ? *settings.schedule : current_schedule()),
      programs_(HillaireShaderOptions{settings.multiple_scattering == MultipleScattering::kOrders,
                                      settings.terrain_shadows, settings.sky_view_steps,
                                      settings.per_pixel_steps, settings.aerial_substeps,
                                      settings.space_view_steps},
                schedule_),
      transmittance_lut_(make_texture_2d(GL_RGBA32F, shared::kTransmittanceLutWidth,
                                         shared::kTransmittanceLutHeight)),
      multiple_scattering_lut_(
          make_texture_2d(GL_RGBA32F, hillaire::kFieldParts * shared::kMultipleScatteringLutWidth,
                          shared::kMultipleScatteringLutHeight)),
      ground_irradiance_lut_(make_texture_2d(GL_RGBA32F, shared::kMultipleScatteringLutWidth, 1)),
      forward_gain_lut_(
          make_texture_2d(GL_R32F, shared::kForwardGainLutWidth, shared::kForwardGainLutHeight)),
      sky_view_lut_(
          make_texture_2d(GL_RGBA16F, shared::kSkyViewLutWidth, shared::kSkyViewLutHeight)),
      aerial_scattering_(make_texture_3d(GL_RGBA16F, shared::kAerialPerspectiveSize,
                                         shared::kAerialPerspectiveSize,
                                         shared::kAerialPerspectiveSize)),
      aerial_transmittance_(make_texture_3d(GL_RGBA16F, shared::kAerialPerspectiveSize,
                                            shared::kAerialPerspectiveSize,
                                            shared::kAerialPerspectiveSize)),
      aerial_shadow_loss_(make_texture_3d(GL_RGBA16F, shared::kAerialPerspectiveSize,
                                          shared::kAerialPerspectiveSize,
                                          shared::kAerialPerspectiveSize)),
      space_open_sky_(
          make_texture_2d(GL_RGBA32F, shared::kSpaceViewLutWidth, shared::kSpaceViewLutHeight)),
      space_scattering_(make_texture_3d(GL_RGBA16F, shared::kSpaceViewLutWidth,
                                        shared::kSpaceViewLutHeight, shared::kSpaceViewLutDepth)),
      space_transmittance_(make_texture_3d(GL_RGBA16F, shared::kSpaceViewLutWidth,
                                           shared::kSpaceViewLutHeight,
                                           shared::kSpaceViewLutDepth)),
      block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
  static_assert(hillaire::kScatteringOrders == int(std::tuple_size_v<decltype(order_luts_)>),
                "one table per order of scattering");
  for (size_t k = 0; k < order_luts_.size(); ++k) {
    const int order = int(k) + 1;
    order_luts_[k] =
        make_texture_2d(GL_RGBA32F, hillaire::kFieldParts * hillaire::scattering_order_width(order),
                        hillaire::scattering_order_height(order) + 1);
  }
  // Zero until a frame fills them; with the paper's LUT the ground's sky
  // light and the moments stay zero.
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(ground_irradiance_lut_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glClearTexImage(multiple_scattering_lut_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  // Single scattering alone: the orders' table and the glow's stay zero.
  if (!settings_.multiple) glClearTexImage(forward_gain_lut_.id(), 0, GL_RED, GL_FLOAT, zero);
  // The sky-view LUT spans the full circle of azimuth: it wraps.
  glTextureParameteri(sky_view_lut_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  // A frame with no surface within the froxels' range leaves them as they
  // are, and the sky pass reads them with a weight of zero: never garbage.
  glClearTexImage(aerial_scattering_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glClearTexImage(aerial_transmittance_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glClearTexImage(aerial_shadow_loss_.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

void HillaireTechnique::update(const AtmosphereModel& model) {
  // The parameters and their block, which is every pass's first input: a
  // change shows in the next frame, with nothing stale.
  model_ = model;
  AtmosphereBlock block = make_atmosphere_block(model);
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
  model_key_ = PassKey().add(block);
  grey_mie_ = block.mie_scattering.x == block.mie_scattering.y &&
              block.mie_scattering.y == block.mie_scattering.z;
}

// What the frame's passes read, decided once before they run: the
// camera as the LUTs see it, the sky view's rounded inputs, the terrain's
// shadow, and the pixels the sky pass shades.
struct HillaireTechnique::FrameState {
  const SkyFrame& frame;
  double r = 0.0, altitude = 0.0;
  // Lifted onto the bottom sphere (a metre above it) when below it: the
  // LUTs describe the sky seen from inside the shell, as the sky pass does.
  glm::dvec3 camera{0.0};
  double r_min = 0.0;
  float lut_r = 0.0f;
  glm::dmat3 local{1.0};
  // The sky-view LUT's inputs, rounded to their steps.
  float sky_view_r = 0.0f;
  glm::vec3 sun_local{0.0f};
  bool shadow = false;      // the terrain's shadow is in the frame
  bool sky_shadow = false;  // ... and the froxels carry what it takes from the open sky
  glm::ivec4 shaded{0};     // the sky pass's pixels: x, y, width, height
  bool space_view = false;  // the sky pass reads the space-view LUT
  float space_r = 0.0f;
  glm::vec3 sun_zenith_local{0.0f};
  glm::ivec4 disk{0};  // the sun's disk's pixels, where the passes that leave it out draw it
};

void HillaireTechnique::prepare(GpuTimer& timer) {
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  prepared_ = true;
  if (!settings_.reuse_passes) graph_.forget();
  graph_.run(model_passes(), timer);
}

// The tables that depend on the model alone (and on the settings, which a
// technique keeps for its life): all run when the model changes.
std::vector<Pass> HillaireTechnique::model_passes() {
  auto model = [this] { return model_key_; };
  std::vector<Pass> passes;
  passes.push_back({.name = "transmittance_lut", .inputs = model, .run = [this] {
                      build_lut(programs_.transmittance, transmittance_lut_, GL_RGBA32F,
                                shared::kTransmittanceLutWidth, shared::kTransmittanceLutHeight);
                      glBindTextureUnit(2, transmittance_lut_.id());
                    }});
  if (!settings_.multiple) return passes;
  passes.push_back({.name = "multiple_scattering_lut",
                    .reads = {"transmittance_lut"},
                    .inputs = model,
                    .run = [this] { compute_multiple_scattering(); }});
  if (settings_.multiple_scattering == MultipleScattering::kOrders) {
    passes.push_back({.name = "forward_gain_lut", .inputs = model, .run = [this] {
                        build_lut(programs_.forward_gain, forward_gain_lut_, GL_R32F,
                                  shared::kForwardGainLutWidth, shared::kForwardGainLutHeight);
                      }});
  }
  return passes;
}

void HillaireTechnique::compute_multiple_scattering() {
  const int w = shared::kMultipleScatteringLutWidth, h = shared::kMultipleScatteringLutHeight;
  if (settings_.multiple_scattering == MultipleScattering::kPaper) {
    build_lut(programs_.multiple_scattering, multiple_scattering_lut_, GL_RGBA32F, w, h);
    return;
  }
  // Each order from the one before, on its grid: h rows of its moments
  // and one row of E_n.
  for (size_t k = 0; k < order_luts_.size(); ++k) {
    const int order = int(k) + 1;
    const Program& program = programs_.orders[k == 0 ? "first" : "next"];
    program.use();
    if (k > 0) {
      glUniform1i(program.uniform("u_order_number"), order);
      glBindTextureUnit(7, order_luts_[k - 1].id());
    }
    bind_image(0, order_luts_[k].id(), GL_RGBA32F, false);
    glDispatchCompute(groups(hillaire::scattering_order_width(order)),
                      groups(hillaire::scattering_order_height(order) + 1), 1);
    glMemoryBarrier(kLutBarrier);
  }
  programs_.orders_sum.use();
  for (size_t k = 0; k < order_luts_.size(); ++k) {
    glBindTextureUnit(GLuint(9 + k), order_luts_[k].id());
  }
  bind_image(0, multiple_scattering_lut_.id(), GL_RGBA32F, false);
  bind_image(1, ground_irradiance_lut_.id(), GL_RGBA32F, false);
  glDispatchCompute(groups(w), groups(h + 1), 1);
  glMemoryBarrier(kLutBarrier);
}

void HillaireTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  FrameState s = frame_state(frame);
  if (!prepared_) prepare(timer);
  prepared_ = false;
  if (!settings_.reuse_passes) graph_.forget();
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(2, transmittance_lut_.id());
  glBindTextureUnit(3, multiple_scattering_lut_.id());
  glBindTextureUnit(8, forward_gain_lut_.id());
  graph_.run(frame_passes(s), timer);
}

// The weight of the LUT path: by altitude, with a blend between, or forced.
void HillaireTechnique::choose_path(double altitude) {
  const double thickness = model_.top_radius - model_.bottom_radius;
  switch (settings_.path) {
    case Path::kLuts:
      lut_weight_ = 1.0;
      break;
    case Path::kPerPixel:
      lut_weight_ = 0.0;
      break;
    case Path::kByAltitude:
      lut_weight_ = 1.0 - smoothstep(settings_.switch_start * thickness,
                                     settings_.switch_end * thickness, altitude);
      break;
  }
}

HillaireTechnique::FrameState HillaireTechnique::frame_state(const SkyFrame& frame) {
  const double bottom = model_.bottom_radius, top = model_.top_radius;
  FrameState s{frame};
  s.r = glm::length(frame.camera_atmo);
  s.altitude = s.r - bottom;
  choose_path(s.altitude);
  s.r_min = bottom + 1.0;
  s.camera = frame.camera_atmo;
  if (s.r < s.r_min) s.camera = s.r > 0.0 ? s.camera * (s.r_min / s.r) : glm::dvec3(0, 0, s.r_min);
  s.lut_r = float(std::clamp(s.r, s.r_min, top));
  // Not out to the horizon, though the march past the froxels is most of
  // the sky's time from a few km up: spread that far, the froxels' slices
  // left the surfaces up to 6 % off the converged march, against 2 %
  // (scripts/aerial_range.sh; docs/techniques/hillaire.md#the-aerial-perspectives-range).
  aerial_range_ = std::max(settings_.aerial_range, 4.0 * s.altitude);
  s.local = local_from_atmo(s.camera, glm::dvec3(frame.sun_dir_atmo));
  round_sky_view_inputs(s);
  s.shadow = settings_.terrain_shadows && frame.terrain_shadow.active();
  s.sky_shadow = sky_shadow(s);
  bound_shaded_pixels(s);
  return s;
}

// The sky-view LUT's inputs: the altitude and the sun's zenith angle in the
// camera's local frame (the LUT puts the sun at azimuth 0), rounded to
// their steps. The sky pass maps its directions with the same rounded
// altitude, so that LUT and lookup agree.
void HillaireTechnique::round_sky_view_inputs(FrameState& s) {
  const double bottom = model_.bottom_radius, top = model_.top_radius;
  const glm::dvec3 sun(s.frame.sun_dir_atmo);
  const double lut_altitude = double(s.lut_r) - bottom;
  // Not in an eclipse: the share hangs on the sun's place to a fraction of
  // its radius, far finer than the steps.
  const bool rounded = settings_.reuse_passes && s.frame.moon_radius <= 0.0f;
  sky_view_altitude_ = std::exp2(quantize(
      std::log2(lut_altitude), rounded ? settings_.sky_view_log2_altitude_step : 0.0));
  s.sky_view_r =
      rounded ? float(std::clamp(bottom + sky_view_altitude_, double(s.r_min), top)) : s.lut_r;
  sky_view_sun_zenith_ =
      quantize(std::acos(std::clamp((s.local * sun).z, -1.0, 1.0)),
               rounded ? glm::radians(settings_.sky_view_sun_zenith_step_deg) : 0.0);
  s.sun_local = rounded ? glm::vec3(float(std::sin(sky_view_sun_zenith_)), 0.0f,
                                    float(std::cos(sky_view_sun_zenith_)))
                        : glm::vec3(s.local * sun);
}

// With the terrain's shadow, the froxels also carry the sunlight it takes
// from the open sky, which the sky-view LUT knows nothing of, unless no
// ray can pass through a shadow: the camera above the highest shadow, and
// no ray of the frame pointing down (an upward ray only climbs).
bool HillaireTechnique::sky_shadow(const FrameState& s) const {
  const SkyFrame& frame = s.frame;
  if (!s.shadow || lut_weight_ <= 0.0) return false;
  if (!frame.view_pruning ||
      s.altitude <= double(frame.terrain_shadow.highest) + kTerrainShadowSoftness) {
    return true;
  }
  const glm::vec3 up(s.camera / glm::length(s.camera));
  bool downward = false;
  for (float x : {-1.0f, 1.0f}) {
    for (float y : {-1.0f, 1.0f}) {
      downward = downward || glm::dot(frame.atmo_ray_from_ndc * glm::vec3(x, y, 1.0f), up) < 0.0f;
    }
  }
  return downward;
}

// From outside the shell, on the per-pixel path alone, the sky pass shades
// only the pixels within the shell's screen bound (with a pixel to spare
// on each side); the others see space, drawn by a pass that costs next to
// nothing and writes what the sky pass would have.
void HillaireTechnique::bound_shaded_pixels(FrameState& s) {
  const SkyFrame& frame = s.frame;
  const double top = model_.top_radius;
  const int w = frame.width, h = frame.height;
  s.shaded = glm::ivec4(0, 0, w, h);
  if (lut_weight_ == 0.0) {
    if (auto bound = sphere_ndc_bound(-frame.camera_atmo, top,
                                      glm::dmat3(frame.atmo_ray_from_ndc))) {
      s.shaded = pixel_rect(*bound, w, h, 2);
    }
  }
  // There, the space-view LUT for the camera's distance and the sun's
  // zenith angle, where the bound holds enough pixels to pay for it, unless
  // the terrain's shadow is in the air (the LUT knows none). The camera
  // stands a kilometre clear of the top, where every ray that meets the
  // shell enters it ahead of the camera. The bound decides it with or
  // without pruning, so that pruning changes no pixel.
  s.space_view = settings_.space_view_lut && lut_weight_ == 0.0 && !s.shadow && s.r > top + 1e3 &&
                 double(s.shaded.z) * double(s.shaded.w) >= settings_.space_view_min_pixels;
  used_space_view_ = s.space_view;
  if (!frame.view_pruning) s.shaded = glm::ivec4(0, 0, w, h);
  s.space_r = float(s.r);
  const double sun_z = std::clamp((s.local * glm::dvec3(frame.sun_dir_atmo)).z, -1.0, 1.0);
  s.sun_zenith_local = glm::vec3(float(std::sqrt(1.0 - sun_z * sun_z)), 0.0f, float(sun_z));
  shaded_fraction_ = double(s.shaded.z) * double(s.shaded.w) / (double(w) * double(h));
  // The sun's disk's screen bound (that of a sphere at a distance of 1
  // along the sun that it fills).
  const std::optional<NdcRect> sun_bound =
      sphere_ndc_bound(glm::dvec3(frame.sun_dir_atmo), std::sin(model_.sun_angular_radius),
                       glm::dmat3(frame.atmo_ray_from_ndc));
  s.disk = sun_bound ? pixel_rect(*sun_bound, w, h, 2) : glm::ivec4(0);
}

// No sky-view LUT and no froxels where the per-pixel path draws alone
// (high up, deep space): a frame models no more than it shows.
std::vector<Pass> HillaireTechnique::frame_passes(FrameState& s) {
  std::vector<Pass> passes;
  passes.push_back({.name = "sky_view_lut",
                    .needed = [this] { return lut_weight_ > 0.0; },
                    .inputs =
                        [this, &s] {
                          return PassKey(model_key_)
                              .add(s.sky_view_r)
                              .add(s.sun_local)
                              .add(s.frame.moon_centre_atmo)
                              .add(s.frame.moon_radius);
                        },
                    .run = [this, &s] { compute_sky_view_lut(s); }});
  passes.push_back({.name = "aerial_perspective",
                    .needed = [this, &s] { return froxels_needed(s); },
                    .inputs = [this, &s] { return froxel_inputs(s); },
                    .run = [this, &s] { compute_aerial_perspective(s); }});
  passes.push_back({.name = "space_view_lut",
                    .needed = [&s] { return s.space_view; },
                    .inputs =
                        [this, &s] {
                          return PassKey(model_key_)
                              .add(s.space_r)
                              .add(s.sun_zenith_local)
                              .add(s.frame.ground_heights);
                        },
                    .run = [this, &s] { compute_space_view_lut(s); }});
  passes.push_back({.name = "space",
                    .needed = [this] { return shaded_fraction_ < 1.0; },
                    .run = [this, &s] { draw_space(s); }});
  // Over what the space pass drew, within the shaded rectangle.
  passes.push_back({.name = "sky",
                    .reads = {"sky_view_lut", "aerial_perspective", "space_view_lut", "space"},
                    .needed = [&s] { return s.shaded.z > 0 && s.shaded.w > 0; },
                    .run = [this, &s] { draw_sky(s); }});
  return passes;
}

void HillaireTechnique::compute_sky_view_lut(const FrameState& s) {
  const Program& program = programs_.sky_view;
  program.use();
  glUniform1f(program.uniform("u_camera_r"), s.sky_view_r);
  glUniform3fv(program.uniform("u_sun_dir_local"), 1, glm::value_ptr(s.sun_local));
  glm::vec3 moon(s.local * glm::dvec3(s.frame.moon_centre_atmo));
  glUniform4f(program.uniform("u_moon"), moon.x, moon.y, moon.z, s.frame.moon_radius);
  bind_image(0, sky_view_lut_.id(), GL_RGBA16F, false);
  // Half the columns: each is written to its mirror image too; all of them
  // in an eclipse, whose shadow has no mirror (sky_view_lut.comp).
  static_assert(shared::kSkyViewLutWidth % 2 == 0, "the sky view's columns pair off");
  const int columns = s.frame.moon_radius > 0.0f ? shared::kSkyViewLutWidth
                                                  : shared::kSkyViewLutWidth / 2;
  glDispatchCompute(groups(columns), groups(shared::kSkyViewLutHeight), 1);
  glMemoryBarrier(kLutBarrier);
}

// The froxels serve surfaces within their range only; none nearer than
// it, none to compute. The drawn tiles' bound answers cheaply from high
// up; near the ground, where a tile's bound holds the camera, the depth
// of the pixels does.
bool HillaireTechnique::froxels_needed(const FrameState& s) {
  const SkyFrame& frame = s.frame;
  return lut_weight_ > 0.0 &&
         (s.sky_shadow || !frame.view_pruning ||
          (frame.nearest_surface <= aerial_range_ &&
           (frame.depth_texture == 0 ||
            surface_probe_.any_nearer(frame.depth_texture, frame.width, frame.height, frame.near,
                                      float(aerial_range_) / frame.atmo_scale_min))));
}

PassKey HillaireTechnique::froxel_inputs(const FrameState& s) const {
  const SkyFrame& frame = s.frame;
  return PassKey(model_key_)
      .add(glm::vec3(s.camera))
      .add(frame.atmo_ray_from_ndc)
      .add(frame.sun_dir_atmo)
      .add(frame.moon_centre_atmo)
      .add(frame.moon_radius)
      .add(float(aerial_range_))
      .add(s.shadow)
      .add(s.shadow ? frame.terrain_shadow.version : 0)
      .add(s.shadow ? frame.terrain_shadow.strength : 0.0f);
}

void HillaireTechnique::compute_aerial_perspective(const FrameState& s) {
  const SkyFrame& frame = s.frame;
  const Program& program = programs_.aerial;
  program.use();
  glUniform3fv(program.uniform("u_camera"), 1, glm::value_ptr(glm::vec3(s.camera)));
  glUniformMatrix3fv(program.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(program.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform4f(program.uniform("u_moon"), frame.moon_centre_atmo.x, frame.moon_centre_atmo.y,
              frame.moon_centre_atmo.z, frame.moon_radius);
  glUniform1f(program.uniform("u_range"), float(aerial_range_));
  bind_image(0, aerial_scattering_.id(), GL_RGBA16F, true);
  bind_image(1, aerial_transmittance_.id(), GL_RGBA16F, true);
  if (settings_.terrain_shadows) {
    bind_image(2, aerial_shadow_loss_.id(), GL_RGBA16F, true);
    bind_terrain_shadow(program, frame.terrain_shadow);
  }
  glDispatchCompute(groups(shared::kAerialPerspectiveSize), groups(shared::kAerialPerspectiveSize),
                    1);
  glMemoryBarrier(kLutBarrier);
}

void HillaireTechnique::compute_space_view_lut(const FrameState& s) {
  const Program& program = programs_.space_view["space_view_lut"];
  program.use();
  glUniform1f(program.uniform("u_camera_r"), s.space_r);
  glUniform3fv(program.uniform("u_sun_dir_local"), 1, glm::value_ptr(s.sun_zenith_local));
  glUniform2fv(program.uniform("u_ground"), 1, glm::value_ptr(s.frame.ground_heights));
  bind_image(0, space_open_sky_.id(), GL_RGBA32F, false);
  bind_image(1, space_scattering_.id(), GL_RGBA16F, true);
  bind_image(2, space_transmittance_.id(), GL_RGBA16F, true);
  glDispatchCompute(groups(shared::kSpaceViewLutWidth), groups(shared::kSpaceViewLutHeight), 1);
  glMemoryBarrier(kLutBarrier);
}

void HillaireTechnique::begin_space(const Program& program, const FrameState& s) {
  const SkyFrame& frame = s.frame;
  sky_pass_.begin(frame.target_framebuffer, frame.width, frame.height, program);
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glUniform3fv(program.uniform("u_camera"), 1, glm::value_ptr(glm::vec3(frame.camera_atmo)));
  glUniformMatrix3fv(program.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(program.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform1f(program.uniform("u_near"), frame.near);
  glUniform4f(program.uniform("u_moon"), frame.moon_centre_atmo.x, frame.moon_centre_atmo.y,
              frame.moon_centre_atmo.z, frame.moon_radius);
}

// The bands around the shaded rectangle (below, above, left, right)
// without the sun's disk, then the disk's bound with it; the sky pass then
// draws the shaded rectangle over whatever of it lay there.
void HillaireTechnique::draw_space(const FrameState& s) {
  const int w = s.frame.width, h = s.frame.height;
  const glm::ivec4& shaded = s.shaded;
  const glm::ivec4 bands[4] = {{0, 0, w, shaded.y},
                               {0, shaded.y + shaded.w, w, h - shaded.y - shaded.w},
                               {0, shaded.y, shaded.x, shaded.w},
                               {shaded.x + shaded.z, shaded.y, w - shaded.x - shaded.z, shaded.w}};
  auto draw_within = [&](const glm::ivec4& rect) {
    if (rect.z <= 0 || rect.w <= 0) return;
    glScissor(rect.x, rect.y, rect.z, rect.w);
    sky_pass_.draw();
  };
  glEnable(GL_SCISSOR_TEST);
  begin_space(programs_.space["unlit"], s);
  for (const glm::ivec4& band : bands) draw_within(band);
  if (s.disk.z > 0 && s.disk.w > 0) {
    begin_space(programs_.space["lit"], s);
    draw_within(s.disk);
  }
  glDisable(GL_SCISSOR_TEST);
}

// Binds the sky pass's inputs for `program` (hillaire_sky.frag).
void HillaireTechnique::begin_sky(const Program& program, const FrameState& s) {
  const SkyFrame& frame = s.frame;
  sky_pass_.begin(frame.target_framebuffer, frame.width, frame.height, program);
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glBindTextureUnit(SkyFrame::kGroundBelowUnit, frame.ground_below_texture);
  glBindTextureUnit(4, sky_view_lut_.id());
  glBindTextureUnit(5, aerial_scattering_.id());
  glBindTextureUnit(6, aerial_transmittance_.id());
  glUniform3fv(program.uniform("u_camera"), 1, glm::value_ptr(glm::vec3(frame.camera_atmo)));
  glUniform1f(program.uniform("u_camera_r"), s.lut_r);
  glUniform1f(program.uniform("u_sky_view_r"), s.sky_view_r);
  glUniformMatrix3fv(program.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(program.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform1f(program.uniform("u_near"), frame.near);
  glUniform4f(program.uniform("u_moon"), frame.moon_centre_atmo.x, frame.moon_centre_atmo.y,
              frame.moon_centre_atmo.z, frame.moon_radius);
  glUniform2f(program.uniform("u_viewport"), float(frame.width), float(frame.height));
  glUniformMatrix3fv(program.uniform("u_local_from_atmo"), 1, GL_FALSE,
                     glm::value_ptr(glm::mat3(s.local)));
  glUniform1f(program.uniform("u_lut_weight"), float(lut_weight_));
  glUniform1f(program.uniform("u_aerial_range"), float(aerial_range_));
  if (settings_.terrain_shadows) {
    bind_terrain_shadow(program, frame.terrain_shadow);
    glBindTextureUnit(kShadowLossUnit, aerial_shadow_loss_.id());
    glUniform1f(program.uniform("u_shadow_loss_weight"), s.sky_shadow ? 1.0f : 0.0f);
  }
}

// The open sky and the surfaces apart, each by a program that serves it
// alone (hillaire_sky.frag's OPEN_SKY_ONLY and SURFACE_ONLY), held by the
// stencil that a classifying pass sets to 1 under the surfaces; the
// stencil was cleared for the frame. bind(program) binds what the two
// programs read besides begin_sky's.
void HillaireTechnique::draw_by_kind(const Program& open_sky, const Program& surfaces,
                                     const FrameState& s,
                                     const std::function<void(const Program&)>& bind) {
  const SkyFrame& frame = s.frame;
  // The classifying pass reads the depth alone.
  sky_pass_.begin(frame.target_framebuffer, frame.width, frame.height, programs_.sky["classify"]);
  glBindTextureUnit(0, frame.depth_texture);
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  sky_pass_.draw();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (const auto& [program, held] : {std::pair{&open_sky, 0}, std::pair{&surfaces, 1}}) {
    begin_sky(*program, s);
    bind(*program);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, held, 0xff);
    sky_pass_.draw();
  }
  glDisable(GL_STENCIL_TEST);
}

void HillaireTechnique::draw_sky(const FrameState& s) {
  const SkyFrame& frame = s.frame;
  if (lut_weight_ == 1.0 && frame.view_pruning) {
    // The LUT path alone: in parts for a software rasteriser, whole for
    // a GPU.
    if (schedule_ == Schedule::kSoftware) {
      draw_sky_in_parts(s);
    } else {
      begin_sky(programs_.sky["whole"], s);
      sky_pass_.draw();
    }
    return;
  }
  // With pruning, a frame on the per-pixel path alone takes the shader
  // without the LUT path (hillaire_sky.frag), for grey Mie with a single
  // read of the glow's gain, and without the terrain's shadow where the
  // frame has none (from above kTerrainShadowTop, as every such frame
  // on Earth and Mars is): the march's sums come out in another order,
  // a few of a float's last bits off (PassReuseGLTest); in six pairs of
  // alternate runs its sky pass ran under the brute force 5.14-5.54x
  // from 400 km (4.59-5.55x with the shadow compiled in) and 5.28-6.13x
  // from 40 000 km (5.45-5.73x). The plain schedule draws the whole
  // shader there, as a GPU runs only the side of a branch it takes.
  if (shaded_fraction_ < 1.0) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(s.shaded.x, s.shaded.y, s.shaded.z, s.shaded.w);
  }
  if (s.space_view) {
    draw_space_view_sky(s);
  } else if (frame.view_pruning && lut_weight_ == 0.0 && schedule_ == Schedule::kSoftware) {
    begin_sky(programs_.sky[per_pixel_sky_variant(grey_mie_, s.shadow)], s);
    sky_pass_.draw();
  } else {
    begin_sky(programs_.sky["whole"], s);
    sky_pass_.draw();
  }
  glDisable(GL_SCISSOR_TEST);
}

void HillaireTechnique::bind_space_view(const Program& program, const FrameState& s) {
  glBindTextureUnit(kSpaceOpenSkyUnit, space_open_sky_.id());
  glBindTextureUnit(kSpaceOpenSkyUnit + 1, space_scattering_.id());
  glBindTextureUnit(kSpaceOpenSkyUnit + 2, space_transmittance_.id());
  glUniform1f(program.uniform("u_space_r"), s.space_r);
  glUniform2fv(program.uniform("u_ground_heights"), 1, glm::value_ptr(s.frame.ground_heights));
}

// The open sky reads the table's whole rays and the lit ground, the
// surfaces its slices: apart for a software rasteriser, in one program for
// a GPU.
void HillaireTechnique::draw_space_view_sky(const FrameState& s) {
  if (schedule_ == Schedule::kPlain) {
    const Program& program = programs_.sky["space_view"];
    begin_sky(program, s);
    bind_space_view(program, s);
    sky_pass_.draw();
    return;
  }
  draw_by_kind(programs_.sky["space_view_open_sky"], programs_.sky["space_view_surfaces"], s,
               [&](const Program& program) { bind_space_view(program, s); });
}

// Every pixel without the march and the sun's disk (the open sky and the
// surfaces apart: draw_by_kind), then the march's tiles (see
// hillaire_sky.frag), then the pixels of the sun's disk. A camera lifted
// onto the bottom sphere raises the rays under its horizon
// (lifted_horizon.glsl), which may carry the disk out of its bound: there
// the first part keeps the disk, with a metre to spare for the shader's
// float |camera| (half a metre a step at Earth's radius).
void HillaireTechnique::draw_sky_in_parts(const FrameState& s) {
  const bool lifted = s.r < s.r_min + 1.0;
  if (lifted) {
    begin_sky(programs_.sky["unmarched"], s);
    sky_pass_.draw();
  } else {
    draw_by_kind(programs_.sky["open_sky"], programs_.sky["surfaces"], s, [](const Program&) {});
  }
  draw_march_tiles(s);
  if (!lifted && s.disk.z > 0 && s.disk.w > 0) {
    begin_sky(programs_.sky["whole"], s);
    glEnable(GL_SCISSOR_TEST);
    glScissor(s.disk.x, s.disk.y, s.disk.z, s.disk.w);
    sky_pass_.draw();
    glDisable(GL_SCISSOR_TEST);
  }
}

// The 8 x 8 tiles with a surface past the froxels' blend, listed on the
// GPU (sky_march_tiles.comp) and drawn by the whole shader as one quad
// each.
void HillaireTechnique::draw_march_tiles(const FrameState& s) {
  const SkyFrame& frame = s.frame;
  const int w = frame.width, h = frame.height;
  const int tiles_x = (w + kMarchTile - 1) / kMarchTile;
  const int tiles_y = (h + kMarchTile - 1) / kMarchTile;
  const size_t tiles = size_t(tiles_x) * size_t(tiles_y);
  const size_t bytes = (4 + 2 * tiles) * sizeof(GLuint);
  if (bytes > march_tiles_bytes_) {
    march_tiles_ = make_buffer(bytes, nullptr);
    march_tiles_bytes_ = bytes;
  }
  const GLuint command[4] = {6, 0, 0, 0};  // six vertices a tile, no tiles yet
  glNamedBufferSubData(march_tiles_.id(), 0, sizeof(command), command);
  const Program& lister = programs_.march_tiles;
  lister.use();
  glBindTextureUnit(0, frame.depth_texture);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMarchTilesBinding, march_tiles_.id());
  glUniformMatrix3fv(lister.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform1f(lister.uniform("u_near"), frame.near);
  glUniform2f(lister.uniform("u_viewport"), float(w), float(h));
  // Where hillaire_sky.frag's blend from the froxels to the march begins.
  glUniform1f(lister.uniform("u_blend_start"), float(0.8 * aerial_range_));
  glDispatchCompute(groups(tiles_x), groups(tiles_y), 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  begin_sky(programs_.sky["tiles"], s);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMarchTilesBinding, march_tiles_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, march_tiles_.id());
  sky_pass_.draw_indirect();
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace planet
