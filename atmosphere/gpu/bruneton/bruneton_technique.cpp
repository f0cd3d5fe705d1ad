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

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>

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
    : settings_(settings),
      schedule_(settings.schedule ? *settings.schedule : current_schedule()),
      block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
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
  if (schedule_ == Schedule::kPlain) {
    all_program_ = pass("kAllPass");
  } else {
    for (int c = 1; c <= 3; ++c) classify_programs_[size_t(c - 1)] = pass("kClassifyPass", c);
    sky_program_ = pass("kSkyPass");
    aerial_program_ = pass("kAerialPass");
    horizon_program_ = pass("kHorizonPass");
  }
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

// The tables a slice at a time: from the disk cache in one, or the
// precompute's passes, each layer of r of a 3D table a slice (they end with
// glFinish: the progress is real, and a long pass never hogs a GPU past its
// watchdog). Each slice binds all it reads and writes: a window draws its
// frames between them.
class BrunetonTechnique::Build final : public TableBuild {
 public:
  Build(BrunetonTechnique& technique, const AtmosphereModel& model)
      : t_(technique), s_(technique.settings_), model_(model), key_(technique.cache_key(model)) {
    if (key_ != t_.key_) add("the tables", 0.0, [this] { begin(); });
  }

  bool step() override {
    if (next_ < slices_.size()) {
      // Moved out first: a slice may add slices.
      Slice slice = std::move(slices_[next_++]);
      slice.run();
      done_ = slice.done;
    }
    return next_ >= slices_.size();
  }
  double fraction() const override { return std::clamp(done_ / total_, 0.0, 1.0); }
  std::string what() const override {
    return next_ < slices_.size() ? slices_[next_].what : std::string("done");
  }

 private:
  struct Slice {
    std::string what;
    double done;  // of total_, once it has run
    std::function<void()> run;
  };
  void add(std::string what, double done, std::function<void()> run) {
    slices_.push_back({std::move(what), done, std::move(run)});
  }

  void begin();
  // The precompute's slices: order 1, then each order from the one before,
  // then the orders' tail; `before` holds the order before's index in the
  // pairs of tables that alternate.
  struct Before {
    int irradiance = 0, multiple = 0;
  };
  void plan_precompute();
  void plan_first_order();
  void plan_order(int order, Before& before);
  void plan_tail(const Before& before);
  void plan_release();
  void keep();
  void end();

  // The precompute's programs, by file and defines.
  void compile(const std::string& name, const char* file, std::vector<std::string> more = {}) {
    add("its programs", done_at_, [this, name, file, more] {
      programs_[name] =
          Program::compute(std::string("atmosphere/gpu/bruneton/") + file, t_.defines(more));
    });
  }
  const Program& use(const std::string& name) {
    const Program& p = programs_.at(name);
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, t_.block_.id());
    p.use();
    glUniform1f(p.uniform("u_mu_s_min"), float(t_.mu_s_min_));
    return p;
  }
  // A pass over the 3D table, a layer of r a slice, `part` of an order
  // from `order_at`; `bind` uses its program and binds its inputs.
  void over_layers(const std::string& what, std::function<const Program&()> bind, GLuint gx,
                   GLuint gy, bool per_layer_z, double order_at, double part) {
    for (int layer = 0; layer < s_.r; ++layer) {
      const double done = order_at + part * double(layer + 1) / s_.r;
      add(what, done, [this, bind, gx, gy, per_layer_z, layer, done] {
        const Program& p = bind();
        glUniform1i(p.uniform("u_first_layer"), layer);
        glDispatchCompute(gx, per_layer_z ? gy : 1, 1);
        {
          DriverWait wait("finishing a layer of the bruneton tables");
          glFinish();
        }
        glMemoryBarrier(kTableBarrier);
        progress_->update(done);
        // Ctrl-C under a command's InterruptScope (without one SIGINT ends
        // the process at once): nothing is kept, the cache is written whole
        // or not at all.
        if (InterruptScope::flag().load()) {
          std::fprintf(stderr,
                       "planet: interrupted: the bruneton tables were not finished and "
                       "nothing of them is kept\n");
          std::exit(kInterruptedExitStatus);
        }
      });
    }
  }

  BrunetonTechnique& t_;
  const Settings& s_;
  AtmosphereModel model_;
  std::string key_;
  std::vector<Slice> slices_;
  size_t next_ = 0;
  double done_ = 0, total_ = 1;
  double done_at_ = 0;  // what the slices being planned leave done
  std::vector<CachedTable> sizes_;
  std::vector<const Texture*> textures_;
  // The precompute's: its progress on stderr, its programs, and each
  // order's ground irradiance and light from the one before: the order
  // before and this one in turn (and the ones before those, for the
  // geometric tail).
  std::optional<Progress> progress_;
  std::map<std::string, Program> programs_;
  Texture irradiance_orders_[2], multiple_orders_[2], delta_rayleigh_, delta_mie_, density_;
  std::chrono::steady_clock::time_point began_;
};

void BrunetonTechnique::Build::begin() {
  // Half-built tables answer to no model.
  t_.key_.clear();
  t_.model_ = model_;
  t_.mu_s_min_ = bruneton_mu_s_min(model_);
  AtmosphereBlock block = make_atmosphere_block(model_);
  glNamedBufferSubData(t_.block_.id(), 0, sizeof(block), &block);
  const int width = s_.nu * s_.mu_s;
  const GLenum format = s_.half ? GL_RGBA16F : GL_RGBA32F;
  t_.transmittance_ = make_texture_2d(GL_RGBA32F, s_.transmittance_width, s_.transmittance_height);
  t_.irradiance_ = make_texture_2d(GL_RGBA32F, s_.irradiance_width, s_.irradiance_height);
  t_.scattering_ = make_texture_3d(format, width, s_.mu, s_.r);
  t_.single_mie_ =
      s_.combined ? make_texture_3d(format, 1, 1, 1) : make_texture_3d(format, width, s_.mu, s_.r);

  sizes_ = {{s_.transmittance_width, s_.transmittance_height, 1, {}},
            {s_.irradiance_width, s_.irradiance_height, 1, {}},
            {width, s_.mu, s_.r, {}}};
  if (!s_.combined) sizes_.push_back({width, s_.mu, s_.r, {}});
  textures_ = {&t_.transmittance_, &t_.irradiance_, &t_.scattering_, &t_.single_mie_};
  if (auto cached = read_bruneton_cache(key_, sizes_)) {
    for (size_t i = 0; i < cached->size(); ++i) {
      const CachedTable& c = (*cached)[i];
      if (c.depth == 1) {
        glTextureSubImage2D(textures_[i]->id(), 0, 0, 0, c.width, c.height, GL_RGBA, GL_FLOAT,
                            c.rgba.data());
      } else {
        glTextureSubImage3D(textures_[i]->id(), 0, 0, 0, 0, c.width, c.height, c.depth, GL_RGBA,
                            GL_FLOAT, c.rgba.data());
      }
    }
    t_.from_cache_ = true;
    t_.precompute_seconds_.clear();
    total_ = 1;
    add("its ground light", 1, [this] { end(); });
    return;
  }
  t_.from_cache_ = false;
  total_ = s_.orders;
  plan_precompute();
  add("writing its cache", s_.orders, [this] { keep(); });
  add("its ground light", s_.orders, [this] { end(); });
}

void BrunetonTechnique::Build::plan_precompute() {
  done_at_ = 0;
  plan_first_order();
  Before before;
  for (int order = 2; order <= s_.orders; ++order) plan_order(order, before);
  // The orders past the last as a geometric series: of the light, from the
  // last two orders of multiple scattering; of the ground's sky light, from
  // the last two of its own (the sky's irradiance runs an order behind).
  if (s_.tail && s_.orders >= 3) plan_tail(before);
  plan_release();
}

// Order 1: transmittance, the sun on the ground, single scattering.
void BrunetonTechnique::Build::plan_first_order() {
  const Settings& s = s_;
  const int width = s.nu * s.mu_s;
  const GLenum scattering_format = s.half ? GL_RGBA16F : GL_RGBA32F;
  const GLuint transmittance = t_.transmittance_.id();
  Texture& scattering = t_.scattering_;
  Texture& single_mie = t_.single_mie_;
  const std::string first = fmt::format("order 1 of {}", s.orders);
  add(first, 0, [this, width] {
    t_.precompute_seconds_.clear();
    progress_.emplace(fmt::format("bruneton tables ({} orders)", s_.orders), s_.orders, "order");
    progress_->update(0);
    began_ = std::chrono::steady_clock::now();
    for (Texture& t : irradiance_orders_) {
      t = make_texture_2d(GL_RGBA32F, s_.irradiance_width, s_.irradiance_height);
    }
    for (Texture* t :
         {&multiple_orders_[0], &multiple_orders_[1], &delta_rayleigh_, &delta_mie_, &density_}) {
      *t = make_texture_3d(GL_RGBA32F, width, s_.mu, s_.r);
    }
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(t_.irradiance_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  });
  compile("transmittance", "transmittance.comp");
  add(first, 0, [this, transmittance] {
    use("transmittance");
    glBindImageTexture(0, transmittance, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groups(s_.transmittance_width, 8), groups(s_.transmittance_height, 8), 1);
    glMemoryBarrier(kTableBarrier);
  });
  compile("direct", "direct_irradiance.comp");
  add(first, 0, [this, transmittance] {
    use("direct");
    glBindTextureUnit(0, transmittance);
    bind_image(0, irradiance_orders_[0], GL_RGBA32F, false);
    glDispatchCompute(groups(s_.irradiance_width, 8), groups(s_.irradiance_height, 8), 1);
    glMemoryBarrier(kTableBarrier);
  });
  compile("single", "single_scattering.comp");
  over_layers(
      first,
      [this, transmittance, &scattering, &single_mie, scattering_format]() -> const Program& {
        const Program& p = use("single");
        glBindTextureUnit(0, transmittance);
        bind_image(0, delta_rayleigh_, GL_RGBA32F, true);
        bind_image(1, delta_mie_, GL_RGBA32F, true);
        bind_image(2, scattering, scattering_format, true);
        if (!s_.combined) bind_image(3, single_mie, scattering_format, true);
        return p;
      },
      groups(width, 8), groups(s.mu, 8), true, 0.0, 1.0);
  done_at_ = 1;
  add(first, 1, [this] { t_.precompute_seconds_.push_back(seconds_since(began_)); });

  compile("density_first", "scattering_density.comp", {"FIRST_ORDER 1"});
  compile("density_next", "scattering_density.comp");
  compile("irradiance_first", "indirect_irradiance.comp", {"FIRST_ORDER 1"});
  compile("irradiance_next", "indirect_irradiance.comp");
  compile("multiple", "multiple_scattering.comp");
}

void BrunetonTechnique::Build::plan_order(int order, Before& before) {
  const Settings& s = s_;
  const int width = s.nu * s.mu_s;
  const GLenum scattering_format = s.half ? GL_RGBA16F : GL_RGBA32F;
  const GLuint transmittance = t_.transmittance_.id(), irradiance = t_.irradiance_.id();
  Texture& scattering = t_.scattering_;
  const int irradiance_before = before.irradiance, multiple_before = before.multiple;
  const std::string what = fmt::format("order {} of {}", order, s.orders);
  const bool after_first = order == 2;
  add(what, order - 1, [this] { began_ = std::chrono::steady_clock::now(); });
  // The density of this order from the order before and the ground lit by
  // the one before that; then the ground's irradiance from the order
  // before, added to the sky's (the same inputs).
  auto inputs = [this, transmittance, after_first, irradiance_before, multiple_before] {
    glBindTextureUnit(0, transmittance);
    if (after_first) {
      glBindTextureUnit(1, delta_rayleigh_.id());
      glBindTextureUnit(2, delta_mie_.id());
    } else {
      glBindTextureUnit(1, multiple_orders_[multiple_before].id());
    }
    glBindTextureUnit(3, irradiance_orders_[irradiance_before].id());
  };
  const std::string density = after_first ? "density_first" : "density_next";
  over_layers(
      what,
      [this, inputs, density]() -> const Program& {
        const Program& p = use(density);
        inputs();
        bind_image(0, density_, GL_RGBA32F, true);
        return p;
      },
      GLuint(s.mu_s), 1, false, order - 1, 0.6);
  add(what, order - 1 + 0.6, [this, inputs, after_first, irradiance, irradiance_before] {
    use(after_first ? "irradiance_first" : "irradiance_next");
    inputs();
    bind_image(0, irradiance_orders_[1 - irradiance_before], GL_RGBA32F, false);
    glBindImageTexture(1, irradiance, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glDispatchCompute(groups(s_.irradiance_width, 8), groups(s_.irradiance_height, 8), 1);
    glMemoryBarrier(kTableBarrier);
  });
  before.irradiance = 1 - irradiance_before;
  // This order's light along every texel's ray, added to the sky's.
  over_layers(
      what,
      [this, transmittance, &scattering, scattering_format, multiple_before]() -> const Program& {
        const Program& p = use("multiple");
        glBindTextureUnit(0, transmittance);
        glBindTextureUnit(1, density_.id());
        bind_image(0, multiple_orders_[1 - multiple_before], GL_RGBA32F, true);
        bind_image(1, scattering, scattering_format, true, GL_READ_WRITE);
        return p;
      },
      groups(width, 8), groups(s.mu, 8), true, order - 1 + 0.6, 0.4);
  before.multiple = 1 - multiple_before;
  done_at_ = order;
  add(what, order, [this] { t_.precompute_seconds_.push_back(seconds_since(began_)); });
}

void BrunetonTechnique::Build::plan_tail(const Before& before) {
  const Settings& s = s_;
  const int width = s.nu * s.mu_s;
  const GLenum scattering_format = s.half ? GL_RGBA16F : GL_RGBA32F;
  const GLuint irradiance = t_.irradiance_.id();
  Texture& scattering = t_.scattering_;
  const int irradiance_before = before.irradiance, multiple_before = before.multiple;
  const std::string what = "the orders' tail";
  add(what, s.orders, [this] { began_ = std::chrono::steady_clock::now(); });
  compile("tail", "geometric_tail.comp");
  over_layers(
      what,
      [this, &scattering, scattering_format, multiple_before]() -> const Program& {
        const Program& p = use("tail");
        glBindTextureUnit(1, multiple_orders_[1 - multiple_before].id());
        glBindTextureUnit(2, multiple_orders_[multiple_before].id());
        bind_image(1, scattering, scattering_format, true, GL_READ_WRITE);
        return p;
      },
      groups(width, 8), groups(s.mu, 8), true, s.orders, 0.0);
  compile("irradiance_tail", "irradiance_tail.comp");
  add(what, s.orders, [this, irradiance, irradiance_before] {
    use("irradiance_tail");
    glBindTextureUnit(1, irradiance_orders_[1 - irradiance_before].id());
    glBindTextureUnit(2, irradiance_orders_[irradiance_before].id());
    glBindImageTexture(1, irradiance, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glDispatchCompute(groups(s_.irradiance_width, 8), groups(s_.irradiance_height, 8), 1);
    glMemoryBarrier(kTableBarrier);
    {
      DriverWait wait("finishing the bruneton irradiance");
      glFinish();
    }
    t_.precompute_seconds_.back() += seconds_since(began_);
  });
}

// The passes' own tables go before the tables are read back.
void BrunetonTechnique::Build::plan_release() {
  add("its tables", s_.orders, [this] {
    progress_->finish();
    progress_.reset();
    programs_.clear();
    for (Texture* t : {&irradiance_orders_[0], &irradiance_orders_[1], &multiple_orders_[0],
                       &multiple_orders_[1], &delta_rayleigh_, &delta_mie_, &density_}) {
      *t = Texture();
    }
    check_gl_errors("BrunetonTechnique::precompute");
  });
}

void BrunetonTechnique::Build::keep() {
  for (auto& t : sizes_) t.rgba.resize(size_t(t.width) * size_t(t.height) * size_t(t.depth) * 4);
  {
    DriverWait wait("reading the bruneton tables back");
    for (size_t i = 0; i < sizes_.size(); ++i) {
      glGetTextureImage(textures_[i]->id(), 0, GL_RGBA, GL_FLOAT,
                        GLsizei(sizes_[i].rgba.size() * sizeof(float)), sizes_[i].rgba.data());
    }
  }
  write_bruneton_cache(key_, sizes_);
  sizes_.clear();
}

void BrunetonTechnique::Build::end() {
  t_.make_ground_irradiance();
  t_.key_ = key_;
  check_gl_errors("BrunetonTechnique::update");
}

std::unique_ptr<TableBuild> BrunetonTechnique::update_in_slices(const AtmosphereModel& model) {
  return std::make_unique<Build>(*this, model);
}

void BrunetonTechnique::update(const AtmosphereModel& model) {
  Build build(*this, model);
  while (!build.step()) {
  }
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

// The stencil's classes (see bruneton_sky.frag): 0 the sky through the
// atmosphere, 1 a surface or the ground, 2 those next to the horizon, 3
// space and the sun alone.
constexpr GLint kSkyClass = 0, kGroundClass = 1, kHorizonClass = 2, kSpaceClass = 3;

void BrunetonTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  set_frame_uniforms(frame);
  std::vector<Pass> passes;
  if (schedule_ == Schedule::kPlain) {
    passes.push_back({.name = "sky", .run = [this, &frame] { draw_every_pixel(frame); }});
  } else {
    passes.push_back({.name = "sky", .run = [this, &frame] { draw_sky(frame); }});
    // The pixels whose class the sky pass set.
    passes.push_back({.name = "aerial", .reads = {"sky"}, .run = [this] { draw_aerial(); }});
  }
  graph_.run(std::move(passes), timer);
}

void BrunetonTechnique::set_frame_uniforms(const SkyFrame& frame) {
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glBindTextureUnit(2, transmittance_.id());
  glBindTextureUnit(3, scattering_.id());
  glBindTextureUnit(4, single_mie_.id());
  glBindTextureUnit(5, irradiance_.id());
  for (const Program* p : {&classify_programs_[0], &classify_programs_[1], &classify_programs_[2],
                           &sky_program_, &aerial_program_, &horizon_program_, &all_program_}) {
    if (p->id() == 0) continue;  // not this schedule's
    p->use();
    glUniform1f(p->uniform("u_mu_s_min"), float(mu_s_min_));
    glUniform3fv(p->uniform("u_camera"), 1, glm::value_ptr(glm::vec3(frame.camera_atmo)));
    glUniformMatrix3fv(p->uniform("u_ray_from_ndc"), 1, GL_FALSE,
                       glm::value_ptr(frame.atmo_ray_from_ndc));
    glUniform3fv(p->uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
    glUniform1f(p->uniform("u_near"), frame.near);
    glUniform4f(p->uniform("u_moon"), frame.moon_centre_atmo.x, frame.moon_centre_atmo.y,
                frame.moon_centre_atmo.z, frame.moon_radius);
  }
}

// The pixels' classes into the stencil, then the sky's pixels.
void BrunetonTechnique::draw_sky(const SkyFrame& frame) {
  sky_pass_.begin(frame.target_framebuffer, frame.width, frame.height, classify_programs_[0]);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (GLint pixel_class : {kGroundClass, kHorizonClass, kSpaceClass}) {
    glStencilFunc(GL_ALWAYS, pixel_class, 0xff);
    classify_programs_[size_t(pixel_class - 1)].use();
    sky_pass_.draw();
  }
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, kSkyClass, 0xff);
  sky_program_.use();
  sky_pass_.draw();
}

// Every pixel by one program, which takes its class in its own branches.
void BrunetonTechnique::draw_every_pixel(const SkyFrame& frame) {
  sky_pass_.begin(frame.target_framebuffer, frame.width, frame.height, all_program_);
  sky_pass_.draw();
}

// The surfaces and the ground, and those next to the horizon.
void BrunetonTechnique::draw_aerial() {
  glStencilFunc(GL_EQUAL, kGroundClass, 0xff);
  aerial_program_.use();
  sky_pass_.draw();
  glStencilFunc(GL_EQUAL, kHorizonClass, 0xff);
  horizon_program_.use();
  sky_pass_.draw();
  glDisable(GL_STENCIL_TEST);
}

}  // namespace planet
