#include "terrain/gpu/terrain_renderer.h"

#include "terrain/sea_brdf.h"

#include "core/error.h"
#include "gl/context.h"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace planet {

// terrain.vert's u_sky_irradiance, terrain.frag's u_day_map and u_night_map.
constexpr GLuint kSkyIrradianceUnit = 15;
constexpr GLuint kDayMapUnit = 13;
constexpr GLuint kNightMapUnit = 14;
// ground_detail.glsl's finest wavelength, metres: the tiles' centres are given in it.
constexpr double kDetailFinest = 0.5;

namespace {

// An equirectangular image as a texture with its mipmaps, repeating in
// longitude.
Texture map_texture(const std::vector<uint8_t>& rgba, int width, int height, GLenum format) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  int levels = 1;
  while ((std::max(width, height) >> levels) > 0) ++levels;
  glTextureStorage2D(id, levels, format, width, height);
  glTextureSubImage2D(id, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glGenerateTextureMipmap(id);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return Texture(id);
}

}  // namespace

LodView TerrainRenderer::lod_view(const Camera& camera, int width, int height,
                                  double pixel_budget) {
  LodView v;
  v.eye_body = camera.pos_body;
  v.view_from_body = glm::mat3_cast(glm::conjugate(camera.body_from_camera));
  v.tan_half_fov_y = std::tan(0.5 * camera.vertical_fov);
  v.aspect = double(width) / double(height);
  v.height_px = height;
  v.pixel_budget = pixel_budget;
  return v;
}

TerrainRenderer::TerrainRenderer(const Body& body, const TerrainOptions& options)
    : options_(options),
      surface_(std::make_unique<TerrainSurface>(body.shape, parse_terrain(body))),
      cache_(std::make_unique<TileCache>(*surface_, options.cache_bytes, options.workers)),
      selector_(*surface_),
      program_(Program::graphics("terrain/gpu/shaders/terrain.vert",
                                 "terrain/gpu/shaders/terrain.frag")) {
  const auto& idx = tile_indices();
  indices_ = make_buffer(idx.size() * sizeof(uint16_t), idx.data(), 0);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glVertexArrayElementBuffer(vao, indices_.id());
  auto attrib = [&](GLuint loc, GLint n, GLenum type, GLboolean norm, size_t offset) {
    glEnableVertexArrayAttrib(vao, loc);
    glVertexArrayAttribFormat(vao, loc, n, type, norm, GLuint(offset));
    glVertexArrayAttribBinding(vao, loc, 0);
  };
  attrib(0, 3, GL_FLOAT, GL_FALSE, offsetof(TileVertex, offset));
  attrib(1, 3, GL_FLOAT, GL_FALSE, offsetof(TileVertex, morph_delta));
  attrib(2, 3, GL_FLOAT, GL_FALSE, offsetof(TileVertex, normal));
  attrib(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(TileVertex, albedo));
  attrib(4, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(TileVertex, horizon));
  attrib(5, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(TileVertex, horizon) + 4);
  attrib(6, 2, GL_HALF_FLOAT, GL_FALSE, offsetof(TileVertex, sea));
  vao_ = VertexArray(vao);
  if (const auto& maps = surface_->config().maps) {
    // The day image's colours stay as stored: terrain.frag maps them to
    // albedo itself; the night image's are radiance, sRGB-encoded.
    day_map_ = map_texture(maps->day_rgba(), maps->width(), maps->height(), GL_RGBA8);
    if (!maps->night_rgba().empty()) {
      night_map_ = map_texture(maps->night_rgba(), maps->night_width(), maps->night_height(),
                               GL_SRGB8_ALPHA8);
    }
  }
  check_gl_errors("TerrainRenderer setup");
}

TerrainRenderer::~TerrainRenderer() = default;

void TerrainRenderer::wait_until_complete(const Camera& camera, int width, int height,
                                          double timeout_s) {
  LodView view = lod_view(camera, width, height, options_.pixel_budget);
  auto start = std::chrono::steady_clock::now();
  // Each round makes the next level resident where the view wants it.
  while (true) {
    LodSelection sel = selector_.select(
        view, [&](const TileKey& k, ResidentTile& t) { return cache_->lookup(k, t); });
    if (sel.wanted.empty()) return;
    cache_->request(sel.wanted);
    double left =
        timeout_s - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<TileKey> missing = cache_->wait_for(sel.wanted, std::max(left, 0.0));
    if (!missing.empty()) {
      std::string names;
      for (size_t i = 0; i < std::min<size_t>(missing.size(), 5); ++i) {
        names += (i ? ", " : "") + missing[i].name();
      }
      throw SystemError(
          fmt::format("terrain: {} tiles (face/level/x/y) still missing after {:.0f} s: {}{}",
                      missing.size(), timeout_s, names, missing.size() > 5 ? ", ..." : ""));
    }
  }
}

void TerrainRenderer::set_uniforms(const Program& program, const Camera& camera,
                                   const LodView& view, int width, int height,
                                   const TerrainLighting& lighting) {
  program.use();
  glm::mat4 clip =
      clip_from_view_reversed_z(camera.vertical_fov, double(width) / height, camera.near);
  glUniformMatrix3fv(program.uniform("u_view_from_body"), 1, GL_FALSE,
                     glm::value_ptr(glm::mat3(view.view_from_body)));
  glUniformMatrix4fv(program.uniform("u_clip_from_view"), 1, GL_FALSE, glm::value_ptr(clip));
  glUniform1i(program.uniform("u_over_datum"), surface_->config().sea_level ? 0 : 1);
  if (&program == &coverage_program_) return;  // no light
  glUniform3fv(program.uniform("u_sun_dir_body"), 1,
               glm::value_ptr(glm::vec3(lighting.sun_dir_body)));
  glUniform1i(program.uniform("u_has_atmosphere"), lighting.has_atmosphere ? 1 : 0);
  // terrain.vert's u_sky_light: 0 none, 1 the technique's table, 2 its own estimate.
  int sky_light = !lighting.sky_light ? 0 : lighting.sky_irradiance != 0 ? 1 : 2;
  glUniform1i(program.uniform("u_sky_light"), sky_light);
  if (lighting.sky_irradiance != 0) glBindTextureUnit(kSkyIrradianceUnit, lighting.sky_irradiance);
  glUniform3fv(program.uniform("u_sun_irradiance"), 1, glm::value_ptr(lighting.solar_irradiance));
  glUniform1i(program.uniform("u_shadows"), lighting.shadows ? 1 : 0);
  // The shadow's edge: the sun's disc, and at least 0.14 degree, a little
  // over the horizon coding's step near level, so that it does not band.
  glUniform1f(program.uniform("u_penumbra"), float(std::max(lighting.sun_angular_radius, 0.0025)));
  glUniform1f(program.uniform("u_sun_angular_radius"), float(lighting.sun_angular_radius));
  // The Moon less the eye in double: float then holds it to 30 m at its
  // distance, 2e-5 of its radius.
  const glm::vec3 moon_rel_eye(lighting.moon_pos_body - camera.pos_body);
  glUniform4f(program.uniform("u_moon_rel_eye"), moon_rel_eye.x, moon_rel_eye.y, moon_rel_eye.z,
              float(lighting.moon_radius));
  if (lighting.has_atmosphere) {
    glm::dvec3 scale = lighting.atmo_scale;
    glUniform3fv(program.uniform("u_atmo_scale"), 1, glm::value_ptr(glm::vec3(scale)));
    glUniform3fv(program.uniform("u_camera_atmo"), 1,
                 glm::value_ptr(glm::vec3(scale * camera.pos_body)));
    glUniform3fv(program.uniform("u_sun_dir_atmo"), 1,
                 glm::value_ptr(glm::vec3(glm::normalize(scale * lighting.sun_dir_body))));
  }
  const auto& maps = surface_->config().maps;
  const SurfacePalette& palette = surface_->config().palette;
  const bool has_sea = surface_->config().sea_level && palette.ocean;
  glUniform1i(program.uniform("u_has_sea"), has_sea ? 1 : 0);
  if (has_sea) {
    glUniform3fv(program.uniform("u_ocean_albedo"), 1, glm::value_ptr(*palette.ocean));
    glUniform1f(program.uniform("u_sea_slope_variance"),
                float(sea::cox_munk_slope_variance(surface_->config().sea_wind)));
    // The sea's normal is the ellipsoid's (terrain.frag's sea_radiance).
    const double f = surface_->shape().flattening;
    glUniform1f(program.uniform("u_geodetic_k"), float((1.0 - f) * (1.0 - f)));
    glUniform3fv(program.uniform("u_camera_body"), 1, glm::value_ptr(glm::vec3(camera.pos_body)));
    glUniform1f(program.uniform("u_sea_radius"),
                float(surface_->shape().equatorial_radius + *surface_->config().sea_level));
  }
  glUniform1i(program.uniform("u_has_day_map"), day_map_.id() != 0 ? 1 : 0);
  glUniform1i(program.uniform("u_has_night_map"), night_map_.id() != 0 ? 1 : 0);
  if (maps) {
    glBindTextureUnit(kDayMapUnit, day_map_.id());
    if (night_map_.id() != 0) glBindTextureUnit(kNightMapUnit, night_map_.id());
    double k = (1.0 - maps->flattening()) * (1.0 - maps->flattening());
    glUniform1f(program.uniform("u_geodetic_k"), float(k));
    glUniform2f(program.uniform("u_map_fade"), float(maps->files().fade_start_m),
                float(maps->files().fade_end_m));
    glUniform1f(program.uniform("u_night_radiance"), float(maps->files().night_radiance));
    // A pixel of the day image on the ground, metres: the mipmap level's unit.
    glUniform1f(program.uniform("u_map_texel_m"),
                float(glm::pi<double>() * surface_->shape().equatorial_radius / maps->height()));
  }
  // Regolith's law for the sun's light (terrain.frag's regolith_sun_term),
  // where the body's file gives one; Lambert's elsewhere.
  const std::optional<Regolith>& regolith = surface_->config().regolith;
  glUniform1i(program.uniform("u_regolith"), regolith ? 1 : 0);
  glUniform1i(program.uniform("u_materials"), surface_->config().palette.materials ? 1 : 0);
  if (regolith) {
    glUniform4f(program.uniform("u_regolith_law"), float(regolith->w), float(regolith->xi),
                float(regolith->b0), float(regolith->h));
    glUniform1f(program.uniform("u_regolith_theta_bar"), float(regolith->theta_bar));
    glUniform1f(program.uniform("u_regolith_normal_albedo"),
                float(regolith_normal_albedo(*regolith)));
  }
}

void TerrainRenderer::draw_tiles(
    const Program& program, const Camera& camera,
    const std::vector<std::pair<const SelectedTile*, const GpuTile*>>& tiles) {
  const GLint center_loc = program.uniform("u_center_rel_eye");
  const GLint morph_loc = program.uniform("u_morph_range");
  const GLint center_body_loc = program.uniform("u_center_body");
  const GLint axis_i_loc = program.uniform("u_axis_i");
  const GLint axis_j_loc = program.uniform("u_axis_j");
  const GLint detail_cell_loc = program.uniform("u_detail_cell");
  const GLint detail_frac_loc = program.uniform("u_detail_frac");
  const auto index_count = GLsizei(tile_indices().size());
  for (const auto& [t, g] : tiles) {
    // The one place a body-frame position meets the camera: in double.
    glm::vec3 center_rel_eye(g->center_body - camera.pos_body);
    glUniform3fv(center_loc, 1, glm::value_ptr(center_rel_eye));
    glUniform2f(morph_loc, float(t->morph_start), float(t->morph_end));
    glUniform3fv(center_body_loc, 1, glm::value_ptr(glm::vec3(g->center_body)));
    glUniform3fv(axis_i_loc, 1, glm::value_ptr(g->axis_i));
    glUniform3fv(axis_j_loc, 1, glm::value_ptr(g->axis_j));
    if (detail_cell_loc >= 0) {
      // The centre in the detail's finest wavelengths, split in double
      // into a cell and a fraction (ground_detail.glsl's precision note).
      glm::dvec3 cells = g->center_body / kDetailFinest;
      glm::dvec3 cell = glm::floor(cells);
      glUniform3i(detail_cell_loc, int(cell.x), int(cell.y), int(cell.z));
      glUniform3fv(detail_frac_loc, 1, glm::value_ptr(glm::vec3(cells - cell)));
    }
    glVertexArrayVertexBuffer(vao_.id(), 0, g->vertices.id(), 0, sizeof(TileVertex));
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_SHORT, nullptr);
  }
}

TerrainStats TerrainRenderer::draw(const Camera& camera, int width, int height,
                                   const TerrainLighting& lighting, GLuint coverage) {
  ++frame_;
  LodView view = lod_view(camera, width, height, options_.pixel_budget);
  LodSelection sel = selector_.select(
      view, [&](const TileKey& k, ResidentTile& t) { return cache_->lookup(k, t); });
  cache_->request(sel.wanted);

  TerrainStats stats;
  stats.tiles_wanted = int(sel.wanted.size());

  // Nearest first: the depth test then turns away the fragments of farther
  // ground behind a ridge before they are shaded.
  std::stable_sort(sel.tiles.begin(), sel.tiles.end(),
                   [](const SelectedTile& a, const SelectedTile& b) {
                     return a.distance < b.distance;
                   });
  // The tiles to draw, on the GPU: both passes draw the same ones.
  std::vector<std::pair<const SelectedTile*, const GpuTile*>> drawn;
  const auto index_count = GLsizei(tile_indices().size());
  for (const SelectedTile& t : sel.tiles) {
    auto it = gpu_tiles_.find(t.key);
    if (it == gpu_tiles_.end()) {
      auto mesh = cache_->use(t.key, frame_);
      if (!mesh) continue;  // selected tiles are resident; evicted meanwhile is impossible
      // A tile leaves the GPU only with the cache, so a tile not on the GPU
      // still has its vertices.
      if (mesh->vertices.empty()) throw std::logic_error("terrain: a tile lost its vertices");
      GpuTile g{make_buffer(mesh->bytes(), mesh->vertices.data(), 0), mesh->center_body,
                mesh->axis_i, mesh->axis_j};
      it = gpu_tiles_.emplace(t.key, std::move(g)).first;
      // One copy is enough: the GPU's.
      cache_->release_vertices(t.key);
    } else {
      cache_->use(t.key, frame_);
    }
    drawn.emplace_back(&t, &it->second);
    ++stats.tiles_drawn;
    stats.triangles += index_count / 3;
    stats.max_error_px = std::max(stats.max_error_px, t.error_px);
    stats.max_level = std::max(stats.max_level, t.key.level);
    stats.nearest_m = std::min(stats.nearest_m, t.distance);
  }
  glBindVertexArray(vao_.id());
  glDisable(GL_CULL_FACE);  // skirts are seen from both sides
  if (coverage != 0) {
    if (!coverage_program_.id()) {
      coverage_program_ =
          Program::graphics("terrain/gpu/shaders/terrain.vert",
                            "terrain/gpu/shaders/terrain_coverage.frag", {"TERRAIN_COVERAGE"});
    }
    GLint lit = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &lit);
    glBindFramebuffer(GL_FRAMEBUFFER, coverage);
    set_uniforms(coverage_program_, camera, view, width, height, lighting);
    draw_tiles(coverage_program_, camera, drawn);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(lit));
  }
  set_uniforms(program_, camera, view, width, height, lighting);
  draw_tiles(program_, camera, drawn);
  for (const TileKey& k : cache_->evict(frame_)) gpu_tiles_.erase(k);
  stats.tiles_resident = cache_->tile_count();
  stats.tiles_on_gpu = gpu_tiles_.size();
  stats.bytes_resident = cache_->bytes();
  check_gl_errors("TerrainRenderer::draw");
  return stats;
}

}  // namespace planet
