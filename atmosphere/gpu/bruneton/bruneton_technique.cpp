#include "atmosphere/gpu/bruneton/bruneton_technique.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "atmosphere/gpu/bruneton/bruneton_cache.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/interrupt.h"
#include "core/progress.h"
#include "gl/context.h"
#include "gl/driver_watch.h"
#include "gl/timer.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace planet {

namespace {

// Bumped whenever the tables computed for the same model, quality and
// shaders change (the code around the shaders, say).
constexpr int kTablesVersion = 3;
constexpr const char* kPrecomputeShaders[] = {
    "transmittance.comp",      "direct_irradiance.comp",   "single_scattering.comp",
    "scattering_density.comp", "indirect_irradiance.comp", "multiple_scattering.comp",
    "geometric_tail.comp",     "irradiance_tail.comp",     "ground_irradiance.comp"};
// What the tables may take of memory at the most: a bad quality is refused
// with a message, not an out-of-memory.
constexpr double kMaxTableBytes = 3.0 * 1024 * 1024 * 1024;
// The one row of the ground's sky light that surfaces read.
constexpr int kGroundIrradianceWidth = 128;
constexpr GLbitfield kTableBarrier =
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;

GLuint groups(int size, int group) { return GLuint((size + group - 1) / group); }

void bind_image(GLuint unit, const Texture& texture, GLenum format, bool layered,
                GLenum access = GL_WRITE_ONLY) {
  glBindImageTexture(unit, texture.id(), 0, layered ? GL_TRUE : GL_FALSE, 0, access, format);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

double bruneton_mu_s_min(const AtmosphereModel& model) {
  // Seen from the bottom, the top of the shell's sunlit air stays lit until
  // the sun is beta below the horizon, cos(beta) = bottom / top; the tables
  // reach 20 % further (for Earth 102.1 deg, near Bruneton's 102).
  double beta = std::acos(model.bottom_radius / model.top_radius);
  return std::cos(0.5 * M_PI + std::min(1.2 * beta, 0.5 * M_PI));
}

uintmax_t BrunetonTechnique::table_file_bytes(const Settings& s) {
  const uintmax_t texel = 4 * sizeof(float);
  const uintmax_t scattering = uintmax_t(s.nu) * s.mu_s * s.mu * s.r;
  return texel * (uintmax_t(s.transmittance_width) * s.transmittance_height +
                  uintmax_t(s.irradiance_width) * s.irradiance_height +
                  scattering * (s.combined ? 1 : 2));
}

BrunetonTechnique::BrunetonTechnique(Settings settings)
    : settings_(settings), block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
  const Settings& s = settings_;
  if (s.mu % 2 != 0) {
    throw InputError(
        fmt::format("bruneton: mu_size={} must be even (half for the rays that "
                    "meet the ground, half for those that do not)",
                    s.mu));
  }
  GLint max_3d = 0, max_2d = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max_3d);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_2d);
  int width = s.nu * s.mu_s;
  if (width > max_3d || s.mu > max_3d || s.r > max_3d) {
    throw InputError(
        fmt::format("bruneton: a scattering table of {} x {} x {} texels "
                    "(nu_size x mu_s_size, mu_size, r_size) is larger than this GL's "
                    "3D textures ({} a side)",
                    width, s.mu, s.r, max_3d));
  }
  if (s.transmittance_width > max_2d || s.irradiance_width > max_2d) {
    throw InputError(
        fmt::format("bruneton: a table is wider than this GL's 2D textures ({})", max_2d));
  }
  // Seven 3D tables at most at once while precomputing, RGBA32F.
  double bytes = 7.0 * 16.0 * double(width) * s.mu * s.r;
  if (bytes > kMaxTableBytes) {
    throw InputError(
        fmt::format("bruneton: tables of {} x {} x {} texels need {:.0f} MiB, more "
                    "than the {:.0f} MiB this program gives them",
                    width, s.mu, s.r, bytes / 1048576.0, kMaxTableBytes / 1048576.0));
  }
  // Each pass and each class is a program of its own: a uniform choosing
  // among them would make llvmpipe run all of them.
  auto pass = [&](const char* which, int pixel_class = 0) {
    return Program::graphics(
        "gl/shaders/fullscreen.vert", "atmosphere/gpu/bruneton/bruneton_sky.frag",
        defines({fmt::format("PASS {}", which), fmt::format("CLASS {}", pixel_class)}));
  };
  for (int c = 1; c <= 3; ++c) classify_programs_[size_t(c - 1)] = pass("kClassifyPass", c);
  sky_program_ = pass("kSkyPass");
  aerial_program_ = pass("kAerialPass");
  horizon_program_ = pass("kHorizonPass");
  ground_irradiance_ = make_texture_2d(GL_RGBA32F, kGroundIrradianceWidth, 1);
}

std::vector<std::string> BrunetonTechnique::defines(std::vector<std::string> more) const {
  const Settings& s = settings_;
  std::vector<std::string> d = {
      fmt::format("TRANSMITTANCE_WIDTH {}", s.transmittance_width),
      fmt::format("TRANSMITTANCE_HEIGHT {}", s.transmittance_height),
      fmt::format("IRRADIANCE_WIDTH {}", s.irradiance_width),
      fmt::format("IRRADIANCE_HEIGHT {}", s.irradiance_height),
      fmt::format("SCATTERING_R {}", s.r),
      fmt::format("SCATTERING_MU {}", s.mu),
      fmt::format("SCATTERING_MU_S {}", s.mu_s),
      fmt::format("SCATTERING_NU {}", s.nu),
      fmt::format("SCATTERING_FORMAT {}", s.half ? "rgba16f" : "rgba32f"),
      fmt::format("INTEGRATION_STEPS {}", s.integration_steps),
      fmt::format("SPHERE_SAMPLES {}", s.sphere_samples),
      fmt::format("TRANSMITTANCE_STEPS {}", s.transmittance_steps),
      // Half a texel of the mu mapping's horizon band, as a cosine.
      fmt::format("HORIZON_BLEND {}", 0.5 / s.mu),
  };
  if (s.combined) d.push_back("COMBINED 1");
  for (auto& m : more) d.push_back(std::move(m));
  return d;
}

std::string BrunetonTechnique::cache_key(const AtmosphereModel& model) const {
  Fnv1a h;
  AtmosphereBlock block = make_atmosphere_block(model);
  h.bytes(&block, sizeof(block));
  const Settings& s = settings_;
  const int values[] = {kTablesVersion,
                        s.transmittance_width,
                        s.transmittance_height,
                        s.irradiance_width,
                        s.irradiance_height,
                        s.r,
                        s.mu,
                        s.mu_s,
                        s.nu,
                        s.orders,
                        s.half,
                        s.combined,
                        s.integration_steps,
                        s.sphere_samples,
                        s.transmittance_steps,
                        s.tail};
  h.bytes(values, sizeof(values));
  // The programs' text as compiled, includes and all: a changed shader
  // never serves tables it did not make.
  for (const char* file : kPrecomputeShaders) {
    std::string source =
        load_shader_source(std::filesystem::path("atmosphere/gpu/bruneton") / file);
    h.bytes(source.data(), source.size());
  }
  double mu_s_min = bruneton_mu_s_min(model);
  h.bytes(&mu_s_min, sizeof(mu_s_min));
  return fmt::format("{:016x}", h.value());
}

void BrunetonTechnique::update(const AtmosphereModel& model) {
  std::string key = cache_key(model);
  if (key == key_) return;  // the same tables
  model_ = model;
  mu_s_min_ = bruneton_mu_s_min(model);
  AtmosphereBlock block = make_atmosphere_block(model);
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
  const Settings& s = settings_;
  const int width = s.nu * s.mu_s;
  const GLenum format = s.half ? GL_RGBA16F : GL_RGBA32F;
  transmittance_ = make_texture_2d(GL_RGBA32F, s.transmittance_width, s.transmittance_height);
  irradiance_ = make_texture_2d(GL_RGBA32F, s.irradiance_width, s.irradiance_height);
  scattering_ = make_texture_3d(format, width, s.mu, s.r);
  single_mie_ =
      s.combined ? make_texture_3d(format, 1, 1, 1) : make_texture_3d(format, width, s.mu, s.r);

  std::vector<CachedTable> sizes = {{s.transmittance_width, s.transmittance_height, 1, {}},
                                    {s.irradiance_width, s.irradiance_height, 1, {}},
                                    {width, s.mu, s.r, {}}};
  if (!s.combined) sizes.push_back({width, s.mu, s.r, {}});
  std::vector<const Texture*> textures = {&transmittance_, &irradiance_, &scattering_,
                                          &single_mie_};
  if (auto cached = read_bruneton_cache(key, sizes)) {
    for (size_t i = 0; i < cached->size(); ++i) {
      const CachedTable& t = (*cached)[i];
      if (t.depth == 1) {
        glTextureSubImage2D(textures[i]->id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_FLOAT,
                            t.rgba.data());
      } else {
        glTextureSubImage3D(textures[i]->id(), 0, 0, 0, 0, t.width, t.height, t.depth, GL_RGBA,
                            GL_FLOAT, t.rgba.data());
      }
    }
    from_cache_ = true;
    precompute_seconds_.clear();
  } else {
    precompute();
    from_cache_ = false;
    for (auto& t : sizes) {
      t.rgba.resize(size_t(t.width) * size_t(t.height) * size_t(t.depth) * 4);
    }
    DriverWait wait("reading the bruneton tables back");
    for (size_t i = 0; i < sizes.size(); ++i) {
      glGetTextureImage(textures[i]->id(), 0, GL_RGBA, GL_FLOAT,
                        GLsizei(sizes[i].rgba.size() * sizeof(float)), sizes[i].rgba.data());
    }
    write_bruneton_cache(key, sizes);
  }
  make_ground_irradiance();
  key_ = key;
  check_gl_errors("BrunetonTechnique::update");
}

void BrunetonTechnique::precompute() {
  const Settings& s = settings_;
  const int width = s.nu * s.mu_s;
  auto compute = [&](const char* file, std::vector<std::string> more = {}) {
    Program p =
        Program::compute(std::string("atmosphere/gpu/bruneton/") + file, defines(std::move(more)));
    p.use();
    glUniform1f(p.uniform("u_mu_s_min"), float(mu_s_min_));
    return p;
  };
  auto use = [&](const Program& p) {
    p.use();
    glUniform1f(p.uniform("u_mu_s_min"), float(mu_s_min_));
  };
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  precompute_seconds_.clear();
  Progress progress(fmt::format("bruneton tables ({} orders)", s.orders), s.orders, "order");
  progress.update(0);
  auto began = std::chrono::steady_clock::now();
  // A pass over the 3D table, a slice of r layers at a time, each finished
  // (glFinish) so that the progress is real and a long pass never hogs a
  // GPU past its watchdog; `part` of an order.
  auto over_layers = [&](const Program& p, GLuint gx, GLuint gy, bool per_layer_z, double order_at,
                         double part) {
    for (int layer = 0; layer < s.r; ++layer) {
      glUniform1i(p.uniform("u_first_layer"), layer);
      if (per_layer_z) {
        glDispatchCompute(gx, gy, 1);
      } else {
        glDispatchCompute(gx, 1, 1);
      }
      {
        DriverWait wait("finishing a layer of the bruneton tables");
        glFinish();
      }
      progress.update(order_at + part * double(layer + 1) / s.r);
      // Ctrl-C under a command's InterruptScope (without one SIGINT ends
      // the process at once): nothing is kept, the cache is written whole
      // or not at all.
      if (InterruptScope::flag().load()) {
        std::fprintf(stderr,
                     "planet: interrupted: the bruneton tables were not finished and "
                     "nothing of them is kept\n");
        std::exit(kInterruptedExitStatus);
      }
    }
    glMemoryBarrier(kTableBarrier);
  };

  // Each order's ground irradiance and light, from the one before: the
  // order before and this one in turn (and the ones before those, for the
  // geometric tail).
  Texture irradiance_orders[2] = {
      make_texture_2d(GL_RGBA32F, s.irradiance_width, s.irradiance_height),
      make_texture_2d(GL_RGBA32F, s.irradiance_width, s.irradiance_height)};
  Texture multiple_orders[2] = {make_texture_3d(GL_RGBA32F, width, s.mu, s.r),
                                make_texture_3d(GL_RGBA32F, width, s.mu, s.r)};
  Texture delta_rayleigh = make_texture_3d(GL_RGBA32F, width, s.mu, s.r);
  Texture delta_mie = make_texture_3d(GL_RGBA32F, width, s.mu, s.r);
  Texture density = make_texture_3d(GL_RGBA32F, width, s.mu, s.r);
  int irradiance_before = 0, multiple_before = 0;  // the order before's index in the pairs
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(irradiance_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  const GLenum scattering_format = s.half ? GL_RGBA16F : GL_RGBA32F;

  // Order 1: transmittance, the sun on the ground, single scattering.
  Program transmittance = compute("transmittance.comp");
  bind_image(0, transmittance_, GL_RGBA32F, false);
  glDispatchCompute(groups(s.transmittance_width, 8), groups(s.transmittance_height, 8), 1);
  glMemoryBarrier(kTableBarrier);
  glBindTextureUnit(0, transmittance_.id());
  Program direct = compute("direct_irradiance.comp");
  bind_image(0, irradiance_orders[irradiance_before], GL_RGBA32F, false);
  glDispatchCompute(groups(s.irradiance_width, 8), groups(s.irradiance_height, 8), 1);
  glMemoryBarrier(kTableBarrier);
  Program single = compute("single_scattering.comp");
  bind_image(0, delta_rayleigh, GL_RGBA32F, true);
  bind_image(1, delta_mie, GL_RGBA32F, true);
  bind_image(2, scattering_, scattering_format, true);
  if (!s.combined) bind_image(3, single_mie_, scattering_format, true);
  over_layers(single, groups(width, 8), groups(s.mu, 8), true, 0.0, 1.0);
  precompute_seconds_.push_back(seconds_since(began));

  Program density_first = compute("scattering_density.comp", {"FIRST_ORDER 1"});
  Program density_next = compute("scattering_density.comp");
  Program irradiance_first = compute("indirect_irradiance.comp", {"FIRST_ORDER 1"});
  Program irradiance_next = compute("indirect_irradiance.comp");
  Program multiple = compute("multiple_scattering.comp");
  for (int order = 2; order <= s.orders; ++order) {
    auto order_began = std::chrono::steady_clock::now();
    const bool after_first = order == 2;
    // The density of this order from the order before and the ground lit by
    // the one before that.
    const Program& d = after_first ? density_first : density_next;
    use(d);
    glBindTextureUnit(0, transmittance_.id());
    if (after_first) {
      glBindTextureUnit(1, delta_rayleigh.id());
      glBindTextureUnit(2, delta_mie.id());
    } else {
      glBindTextureUnit(1, multiple_orders[multiple_before].id());
    }
    glBindTextureUnit(3, irradiance_orders[irradiance_before].id());
    bind_image(0, density, GL_RGBA32F, true);
    over_layers(d, GLuint(s.mu_s), 1, false, order - 1, 0.6);
    // The ground's irradiance from the order before, added to the sky's.
    const Program& e = after_first ? irradiance_first : irradiance_next;
    use(e);
    bind_image(0, irradiance_orders[1 - irradiance_before], GL_RGBA32F, false);
    bind_image(1, irradiance_, GL_RGBA32F, false, GL_READ_WRITE);
    glDispatchCompute(groups(s.irradiance_width, 8), groups(s.irradiance_height, 8), 1);
    glMemoryBarrier(kTableBarrier);
    irradiance_before = 1 - irradiance_before;
    // This order's light along every texel's ray, added to the sky's.
    use(multiple);
    glBindTextureUnit(0, transmittance_.id());
    glBindTextureUnit(1, density.id());
    bind_image(0, multiple_orders[1 - multiple_before], GL_RGBA32F, true);
    bind_image(1, scattering_, scattering_format, true, GL_READ_WRITE);
    over_layers(multiple, groups(width, 8), groups(s.mu, 8), true, order - 1 + 0.6, 0.4);
    multiple_before = 1 - multiple_before;
    precompute_seconds_.push_back(seconds_since(order_began));
  }
  // The orders past the last as a geometric series: of the light, from the
  // last two orders of multiple scattering; of the ground's sky light, from
  // the last two of its own (the sky's irradiance runs an order behind).
  if (s.tail && s.orders >= 3) {
    auto tail_began = std::chrono::steady_clock::now();
    Program tail = compute("geometric_tail.comp");
    glBindTextureUnit(1, multiple_orders[1 - multiple_before].id());
    glBindTextureUnit(2, multiple_orders[multiple_before].id());
    bind_image(1, scattering_, scattering_format, true, GL_READ_WRITE);
    over_layers(tail, groups(width, 8), groups(s.mu, 8), true, s.orders, 0.0);
    Program irradiance_tail = compute("irradiance_tail.comp");
    glBindTextureUnit(1, irradiance_orders[1 - irradiance_before].id());
    glBindTextureUnit(2, irradiance_orders[irradiance_before].id());
    bind_image(1, irradiance_, GL_RGBA32F, false, GL_READ_WRITE);
    glDispatchCompute(groups(s.irradiance_width, 8), groups(s.irradiance_height, 8), 1);
    glMemoryBarrier(kTableBarrier);
    {
      DriverWait wait("finishing the bruneton irradiance");
      glFinish();
    }
    precompute_seconds_.back() += seconds_since(tail_began);
  }
  progress.finish();
  check_gl_errors("BrunetonTechnique::precompute");
}

void BrunetonTechnique::make_ground_irradiance() {
  Program p = Program::compute("atmosphere/gpu/bruneton/ground_irradiance.comp", defines({}));
  p.use();
  glUniform1f(p.uniform("u_mu_s_min"), float(mu_s_min_));
  glUniform1i(p.uniform("u_width"), kGroundIrradianceWidth);
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, irradiance_.id());
  bind_image(0, ground_irradiance_, GL_RGBA32F, false);
  glDispatchCompute(groups(kGroundIrradianceWidth, 64), 1, 1);
  glMemoryBarrier(kTableBarrier);
}

void BrunetonTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glBindTextureUnit(2, transmittance_.id());
  glBindTextureUnit(3, scattering_.id());
  glBindTextureUnit(4, single_mie_.id());
  glBindTextureUnit(5, irradiance_.id());
  for (const Program* p :
       {&classify_programs_[0], &classify_programs_[1], &classify_programs_[2], &sky_program_,
        &aerial_program_, &horizon_program_}) {
    p->use();
    glUniform1f(p->uniform("u_mu_s_min"), float(mu_s_min_));
    glUniform3fv(p->uniform("u_camera"), 1, glm::value_ptr(glm::vec3(frame.camera_atmo)));
    glUniformMatrix3fv(p->uniform("u_ray_from_ndc"), 1, GL_FALSE,
                       glm::value_ptr(frame.atmo_ray_from_ndc));
    glUniform3fv(p->uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
    glUniform1f(p->uniform("u_near"), frame.near);
  }
  // The stencil's classes (see bruneton_sky.frag): 0 the sky through the
  // atmosphere, 1 a surface or the ground, 2 those next to the horizon, 3
  // space and the sun alone.
  constexpr GLint kSky = 0, kGround = 1, kHorizon = 2, kSpace = 3;
  timer.begin("sky");
  sky_pass_.begin(frame.target_framebuffer, frame.width, frame.height, classify_programs_[0]);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (GLint pixel_class : {kGround, kHorizon, kSpace}) {
    glStencilFunc(GL_ALWAYS, pixel_class, 0xff);
    classify_programs_[size_t(pixel_class - 1)].use();
    sky_pass_.draw();
  }
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, kSky, 0xff);
  sky_program_.use();
  sky_pass_.draw();
  timer.end();
  timer.begin("aerial");
  glStencilFunc(GL_EQUAL, kGround, 0xff);
  aerial_program_.use();
  sky_pass_.draw();
  glStencilFunc(GL_EQUAL, kHorizon, 0xff);
  horizon_program_.use();
  sky_pass_.draw();
  glDisable(GL_STENCIL_TEST);
  timer.end();
}

}  // namespace planet
