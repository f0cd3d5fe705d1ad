#include "atmosphere/gpu/oneil/oneil_technique.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "core/progress.h"
#include "gl/context.h"
#include "gl/timer.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

namespace planet {

namespace {

// A pixel whose surface lies this much (relative) nearer or farther than
// the grid's interpolated distance evaluates its own ray: a silhouette
// between a near slope and far terrain, which no interpolation serves.
constexpr double kDistanceTolerance = 0.05;

// Two triangles per cell of a (columns + 1) x (rows + 1) grid of vertices
// numbered row by row.
std::vector<GLuint> grid_indices(int columns, int rows) {
  std::vector<GLuint> indices;
  indices.reserve(size_t(columns) * size_t(rows) * 6);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      GLuint a = GLuint(j * (columns + 1) + i), b = a + 1;
      GLuint c = a + GLuint(columns + 1), d = c + 1;
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  }
  return indices;
}

VertexArray indexed_vao(const Buffer& indices) {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glVertexArrayElementBuffer(vao, indices.id());
  return VertexArray(vao);
}

void set_scale_uniforms(const Program& p, const oneil::OneilScale& rayleigh,
                        const oneil::OneilScale& mie) {
  float r[oneil::kOneilTerms], m[oneil::kOneilTerms];
  for (int i = 0; i < oneil::kOneilTerms; ++i) {
    r[i] = float(rayleigh.c[i]);
    m[i] = float(mie.c[i]);
  }
  glUniform1fv(p.uniform("u_rayleigh_c"), oneil::kOneilTerms, r);
  glUniform1fv(p.uniform("u_mie_c"), oneil::kOneilTerms, m);
  glUniform2f(p.uniform("u_scale_heights"), float(rayleigh.scale_height), float(mie.scale_height));
  glUniform1i(p.uniform("u_scale_kind"), rayleigh.kind);
}

}  // namespace

OneilTechnique::OneilTechnique(Settings settings)
    : settings_(settings), block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
  std::vector<std::string> defines = {
      fmt::format("SAMPLES {}", settings_.samples),
      fmt::format("DISTANCE_TOLERANCE {}", kDistanceTolerance),
  };
  if (settings_.chapter_exposure) defines.push_back("CHAPTER_EXPOSURE 1");
  dome_program_ = Program::graphics("atmosphere/gpu/oneil/oneil_dome.vert",
                                    "atmosphere/gpu/oneil/oneil_dome.frag", defines);
  ground_program_ = Program::graphics("atmosphere/gpu/oneil/oneil_ground.vert",
                                      "atmosphere/gpu/oneil/oneil_ground.frag", defines);
  // The dome: rings 0..dome, 2 dome segments around (the last column
  // repeats the first, so that the mesh closes).
  std::vector<GLuint> dome = grid_indices(2 * settings_.dome, settings_.dome);
  dome_index_count_ = GLsizei(dome.size());
  dome_indices_ = make_buffer(dome.size() * sizeof(GLuint), dome.data(), 0);
  dome_vao_ = indexed_vao(dome_indices_);
  check_gl_errors("OneilTechnique setup");
}

void OneilTechnique::update(const AtmosphereModel& model) {
  AtmosphereBlock block = make_atmosphere_block(model);
  if (has_model_ && std::memcmp(&block, &block_values_, sizeof(block)) == 0) return;
  block_values_ = block;
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
  auto began = std::chrono::steady_clock::now();
  fitted_ = oneil::fit_body_scales(model);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  if (settings_.scale == Scale::kFitted) {
    rayleigh_ = fitted_.rayleigh;
    mie_ = fitted_.mie;
  } else {
    rayleigh_ = oneil::chapter_scale(fitted_.rayleigh.scale_height);
    mie_ = oneil::chapter_scale(fitted_.mie.scale_height);
  }
  if (progress_shown()) {
    std::fprintf(
        stderr,
        "oneil: scale functions fitted in %.2f s; worst optical-depth error %.2f %% "
        "Rayleigh (H %.4g km), %.2f %% Mie (H %.4g km)%s\n",
        seconds, 100 * fitted_.rayleigh_error.worst_relative, fitted_.rayleigh.scale_height / 1e3,
        100 * fitted_.mie_error.worst_relative, fitted_.mie.scale_height / 1e3,
        settings_.scale == Scale::kChapter ? "; drawing with the chapter's polynomial" : "");
  }
  model_ = model;
  has_model_ = true;
}

void OneilTechnique::set_frame_uniforms(const Program& p, const SkyFrame& frame) const {
  p.use();
  glUniform3fv(p.uniform("u_camera"), 1, glm::value_ptr(glm::vec3(frame.camera_atmo)));
  glUniformMatrix3fv(p.uniform("u_ray_from_ndc"), 1, GL_FALSE,
                     glm::value_ptr(frame.atmo_ray_from_ndc));
  glUniform3fv(p.uniform("u_sun_dir"), 1, glm::value_ptr(frame.sun_dir_atmo));
  glUniform1f(p.uniform("u_near"), frame.near);
  glUniform2f(p.uniform("u_viewport"), float(frame.width), float(frame.height));
  glUniform1f(p.uniform("u_exposure"), frame.exposure);
  set_scale_uniforms(p, rayleigh_, mie_);
}

void OneilTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  const int cell = settings_.cell;
  const int columns = (frame.width + cell - 1) / cell, rows = (frame.height + cell - 1) / cell;
  if (columns != grid_width_ || rows != grid_height_) {
    std::vector<GLuint> grid = grid_indices(columns, rows);
    grid_index_count_ = GLsizei(grid.size());
    grid_indices_ = make_buffer(grid.size() * sizeof(GLuint), grid.data(), 0);
    grid_vao_ = indexed_vao(grid_indices_);
    grid_width_ = columns;
    grid_height_ = rows;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, frame.target_framebuffer);
  glViewport(0, 0, frame.width, frame.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  const float black[4] = {0, 0, 0, 1};
  glClearBufferfv(GL_COLOR, 0, black);
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);

  // The camera's vertical and two horizontals for the dome, in double: the
  // camera may be 1e9 m out.
  glm::dvec3 camera = frame.camera_atmo;
  glm::dvec3 up = glm::normalize(camera);
  glm::dvec3 any = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  glm::dvec3 east = glm::normalize(glm::cross(any, up));
  glm::dvec3 north = glm::cross(up, east);
  bool outside = glm::length(camera) >= model_.top_radius;

  timer.begin("sky");
  set_frame_uniforms(dome_program_, frame);
  glUniform1i(dome_program_.uniform("u_rings"), settings_.dome);
  glUniform1i(dome_program_.uniform("u_segments"), 2 * settings_.dome);
  glUniform3fv(dome_program_.uniform("u_up"), 1, glm::value_ptr(glm::vec3(up)));
  glUniform3fv(dome_program_.uniform("u_east"), 1, glm::value_ptr(glm::vec3(east)));
  glUniform3fv(dome_program_.uniform("u_north"), 1, glm::value_ptr(glm::vec3(north)));
  glUniform1i(dome_program_.uniform("u_outside"), outside ? 1 : 0);
  glm::mat3 ndc_from_ray = glm::inverse(frame.atmo_ray_from_ndc);
  glUniformMatrix3fv(dome_program_.uniform("u_ndc_from_ray"), 1, GL_FALSE,
                     glm::value_ptr(ndc_from_ray));
  glBindVertexArray(dome_vao_.id());
  glDrawElements(GL_TRIANGLES, dome_index_count_, GL_UNSIGNED_INT, nullptr);
  timer.end();

  timer.begin("aerial");
  set_frame_uniforms(ground_program_, frame);
  glUniform1i(ground_program_.uniform("u_cell"), cell);
  glUniform1i(ground_program_.uniform("u_columns"), columns);
  glBindVertexArray(grid_vao_.id());
  glDrawElements(GL_TRIANGLES, grid_index_count_, GL_UNSIGNED_INT, nullptr);
  timer.end();
  check_gl_errors("OneilTechnique::render");
}

}  // namespace planet
