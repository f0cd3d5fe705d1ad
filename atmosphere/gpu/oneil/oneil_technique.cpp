#include "atmosphere/gpu/oneil/oneil_technique.h"

#include "atmosphere/gpu/atmosphere_block.h"
#include "core/progress.h"
#include "gl/context.h"
#include "gl/timer.h"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace planet {

namespace {

// A pixel whose surface lies this much (relative) nearer or farther than
// the grid's interpolated distance evaluates its own ray: a silhouette
// between a near slope and far terrain, which no interpolation serves.
constexpr double kDistanceTolerance = 0.05;

// The stencil's classes of pixels, which restrict each pass to the pixels
// it serves (see SkyFrame::target_framebuffer): the grid's (a surface or
// the bottom sphere) until served, those the grid served (marked by
// incrementing), and the sky's.
constexpr GLint kGridPixel = 0, kServedPixel = 1, kSkyPixel = 2;

// The cells of a columns x rows grid of `cell` pixels that hold the sphere
// of `radius` about the centre as the frame sees it: the whole grid from
// inside the sphere or where its outline reaches behind the camera, none
// where it is all behind. [first, last) in x and y.
struct CellRange {
  glm::ivec2 first{0}, last{0};
};

CellRange cells_of_sphere(const SkyFrame& frame, double radius, int cell, int columns, int rows) {
  CellRange all{{0, 0}, {columns, rows}};
  glm::dvec3 camera = frame.camera_atmo;
  double distance = glm::length(camera);
  if (distance <= radius * 1.001) return all;
  // The outline: 64 directions on the cone of half-angle asin(radius / d)
  // about the direction to the centre, widened so that the chords between
  // them still hold the outline (1 / cos(pi / 64)).
  glm::dvec3 to_centre = -camera / distance;
  glm::dvec3 any = std::abs(to_centre.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  glm::dvec3 e1 = glm::normalize(glm::cross(any, to_centre)), e2 = glm::cross(to_centre, e1);
  double half_angle = std::asin(radius / distance);
  double tan_half = std::tan(half_angle) / std::cos(glm::pi<double>() / 64.0);
  glm::dmat3 ndc_from_ray = glm::inverse(glm::dmat3(frame.atmo_ray_from_ndc));
  glm::dvec2 low(1e30), high(-1e30);
  int behind = 0;
  for (int k = 0; k < 64; ++k) {
    double a = 2.0 * glm::pi<double>() * k / 64.0;
    glm::dvec3 dir = to_centre + tan_half * (std::cos(a) * e1 + std::sin(a) * e2);
    glm::dvec3 q = ndc_from_ray * dir;
    if (q.z <= 0.0) {
      ++behind;
      continue;
    }
    low = glm::min(low, glm::dvec2(q) / q.z);
    high = glm::max(high, glm::dvec2(q) / q.z);
  }
  if (behind == 64) return {};
  if (behind > 0) return all;
  // NDC to cells, a cell wider on each side for the interpolation's edge.
  auto to_cell = [&](double ndc, int pixels) { return (ndc * 0.5 + 0.5) * pixels / cell; };
  glm::ivec2 first(int(std::floor(to_cell(low.x, frame.width))) - 1,
                   int(std::floor(to_cell(low.y, frame.height))) - 1);
  glm::ivec2 last(int(std::ceil(to_cell(high.x, frame.width))) + 1,
                  int(std::ceil(to_cell(high.y, frame.height))) + 1);
  first = glm::clamp(first, glm::ivec2(0), glm::ivec2(columns, rows));
  last = glm::clamp(last, first, glm::ivec2(columns, rows));
  return {first, last};
}

// The runs [first, last) of the dome's `segments` sectors of azimuth about
// `up` (from `east` toward `north`) that the frame can see, from the rays of
// a 33 x 33 lattice over the screen, each sector within two of a seen one
// kept (the lattice's rays are no further apart than that). All of them
// where the view holds the vertical, about which every sector meets.
std::vector<glm::ivec2> visible_sectors(const SkyFrame& frame, const glm::dvec3& up,
                                        const glm::dvec3& east, const glm::dvec3& north,
                                        int segments) {
  glm::dmat3 ray_from_ndc(frame.atmo_ray_from_ndc);
  glm::dmat3 ndc_from_ray = glm::inverse(ray_from_ndc);
  for (glm::dvec3 axis : {up, -up}) {
    glm::dvec3 q = ndc_from_ray * axis;
    if (q.z > 0.0 && std::abs(q.x) <= 1.0 * q.z && std::abs(q.y) <= 1.0 * q.z) {
      return {{0, segments}};
    }
  }
  std::vector<bool> seen(size_t(segments), false);
  constexpr int kLattice = 33;
  for (int j = 0; j < kLattice; ++j) {
    for (int i = 0; i < kLattice; ++i) {
      glm::dvec3 ray = ray_from_ndc * glm::dvec3(2.0 * i / (kLattice - 1) - 1.0,
                                                 2.0 * j / (kLattice - 1) - 1.0, 1.0);
      double azimuth = std::atan2(glm::dot(ray, north), glm::dot(ray, east));
      int sector = int(std::floor(azimuth / (2.0 * glm::pi<double>()) * segments));
      for (int k = sector - 2; k <= sector + 2; ++k)
        seen[size_t(((k % segments) + segments) % segments)] = true;
    }
  }
  std::vector<glm::ivec2> runs;
  for (int k = 0; k < segments; ++k) {
    if (!seen[size_t(k)]) continue;
    if (!runs.empty() && runs.back().y == k) {
      runs.back().y = k + 1;
    } else {
      runs.push_back({k, k + 1});
    }
  }
  return runs;
}

// Shades only the pixels of one class; keeps their class.
void shade_only(GLint stencil_class) {
  glStencilFunc(GL_EQUAL, stencil_class, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
}

// Two triangles per cell of a (columns + 1) x (rows + 1) grid of vertices
// numbered row by row.
// The two triangles of cell (i, j) of a mesh with `columns` cells a row,
// whose vertex (i, j) is j (columns + 1) + i.
void add_cell(std::vector<GLuint>& indices, int columns, int i, int j) {
  GLuint a = GLuint(j * (columns + 1) + i), b = a + 1;
  GLuint c = a + GLuint(columns + 1), d = c + 1;
  indices.insert(indices.end(), {a, b, d, a, d, c});
}

// A frame's cells go to the GPU as one index list and are drawn in one
// call: llvmpipe shades a vertex once a draw, so a draw per row of cells
// shaded every row of vertices twice (the dome's sums, at 8 samples, are
// most of its pass).
void draw_cells(const Buffer& buffer, const VertexArray& vao, const std::vector<GLuint>& indices) {
  if (indices.empty()) return;
  glNamedBufferSubData(buffer.id(), 0, GLsizeiptr(indices.size() * sizeof(GLuint)),
                       indices.data());
  glBindVertexArray(vao.id());
  glDrawElements(GL_TRIANGLES, GLsizei(indices.size()), GL_UNSIGNED_INT, nullptr);
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
}

}  // namespace

OneilTechnique::OneilTechnique(Settings settings)
    : settings_(settings), block_(make_buffer(sizeof(AtmosphereBlock), nullptr)) {
  std::vector<std::string> defines = {
      fmt::format("SAMPLES {}", settings_.samples),
      fmt::format("DISTANCE_TOLERANCE {}", kDistanceTolerance),
      fmt::format("SCALE_KIND {}",
                  settings_.scale == Scale::kChapter ? oneil::kOneilChapter : oneil::kOneilFitted),
  };
  if (settings_.chapter_exposure) defines.push_back("CHAPTER_EXPOSURE 1");
  dome_program_ = Program::graphics("atmosphere/gpu/oneil/oneil_dome.vert",
                                    "atmosphere/gpu/oneil/oneil_dome.frag", defines);
  ground_program_ = Program::graphics("atmosphere/gpu/oneil/oneil_ground.vert",
                                      "atmosphere/gpu/oneil/oneil_ground.frag", defines);
  classify_program_ = Program::graphics("gl/shaders/fullscreen.vert",
                                        "atmosphere/gpu/oneil/oneil_classify.frag", defines);
  pixel_program_ = Program::graphics("gl/shaders/fullscreen.vert",
                                     "atmosphere/gpu/oneil/oneil_pixel.frag", defines);
  // The dome: rings 0..dome, 2 dome segments around (the last column
  // repeats the first, so that the mesh closes); room for all its cells.
  dome_indices_ = make_buffer(size_t(settings_.dome) * size_t(2 * settings_.dome) * 6 *
                                  sizeof(GLuint),
                              nullptr);
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
  glUniform4f(p.uniform("u_moon"), frame.moon_centre_atmo.x, frame.moon_centre_atmo.y,
              frame.moon_centre_atmo.z, frame.moon_radius);
  set_scale_uniforms(p, rayleigh_, mie_);
}

void OneilTechnique::render(const SkyFrame& frame, GpuTimer& timer) {
  const int cell = settings_.cell;
  const int columns = (frame.width + cell - 1) / cell, rows = (frame.height + cell - 1) / cell;
  if (columns != grid_width_ || rows != grid_height_) {
    grid_indices_ = make_buffer(size_t(columns) * size_t(rows) * 6 * sizeof(GLuint), nullptr);
    grid_vao_ = indexed_vao(grid_indices_);
    grid_width_ = columns;
    grid_height_ = rows;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, frame.target_framebuffer);
  glViewport(0, 0, frame.width, frame.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, block_.id());
  glBindTextureUnit(0, frame.depth_texture);
  glBindTextureUnit(1, frame.surface_texture);
  glEnable(GL_STENCIL_TEST);
  // Each pass shades the pixels of its class alone (the stencil's, which
  // the classifying pass sets and the grid's pass increments where served).
  std::vector<Pass> passes;
  passes.push_back({.name = "classify", .run = [this, &frame] { classify(frame); }});
  passes.push_back(
      {.name = "sky", .reads = {"classify"}, .run = [this, &frame] { draw_dome(frame); }});
  passes.push_back(
      {.name = "aerial", .reads = {"classify"}, .run = [this, &frame] { draw_grid(frame); }});
  passes.push_back(
      {.name = "own_rays", .reads = {"aerial"}, .run = [this, &frame] { draw_own_rays(frame); }});
  graph_.run(std::move(passes), timer);
  glDisable(GL_STENCIL_TEST);
  check_gl_errors("OneilTechnique::render");
}

// Every pixel: the sky's are marked, and given the sun as seen from space.
void OneilTechnique::classify(const SkyFrame& frame) {
  set_frame_uniforms(classify_program_, frame);
  glStencilFunc(GL_ALWAYS, kSkyPixel, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  fullscreen_.draw();
}

// From outside, the dome is the ring between the planet's disk and the
// limb, a few pixels wide from far away: rings no closer than half a
// pixel (they crowd toward both edges), but never fewer than 16 (with 4,
// the 32x16 asteroid_space scene went from 30.5 to 33.9 % in red; with
// 16 its error is unchanged). From 40 000 km that is a third of the
// dome's vertices and their sums.
int OneilTechnique::dome_rings(const SkyFrame& frame) const {
  const double r = glm::length(frame.camera_atmo);
  if (r < model_.top_radius) return settings_.dome;
  double width = std::asin(std::min(model_.top_radius / r, 1.0)) -
                 std::asin(std::min(model_.bottom_radius / r, 1.0));
  // The angle of one pixel at the centre of the view: the rays of NDC
  // y = 0 and y = 2 / height.
  glm::dvec3 centre = glm::dmat3(frame.atmo_ray_from_ndc) * glm::dvec3(0, 0, 1);
  glm::dvec3 next = glm::dmat3(frame.atmo_ray_from_ndc) * glm::dvec3(0, 2.0 / frame.height, 1);
  double pixel = std::acos(std::min(glm::dot(glm::normalize(centre), glm::normalize(next)), 1.0));
  return std::clamp(int(std::ceil(2 * width / std::max(pixel, 1e-9))), 16, settings_.dome);
}

void OneilTechnique::draw_dome(const SkyFrame& frame) {
  // The camera's vertical and two horizontals for the dome, in double: the
  // camera may be 1e9 m out.
  glm::dvec3 camera = frame.camera_atmo;
  glm::dvec3 up = glm::normalize(camera);
  glm::dvec3 any = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  glm::dvec3 east = glm::normalize(glm::cross(any, up));
  glm::dvec3 north = glm::cross(up, east);
  bool outside = glm::length(camera) >= model_.top_radius;
  const int rings = dome_rings(frame);
  set_frame_uniforms(dome_program_, frame);
  glUniform1i(dome_program_.uniform("u_rings"), rings);
  glUniform1i(dome_program_.uniform("u_segments"), 2 * settings_.dome);
  glUniform3fv(dome_program_.uniform("u_up"), 1, glm::value_ptr(glm::vec3(up)));
  glUniform3fv(dome_program_.uniform("u_east"), 1, glm::value_ptr(glm::vec3(east)));
  glUniform3fv(dome_program_.uniform("u_north"), 1, glm::value_ptr(glm::vec3(north)));
  glUniform1i(dome_program_.uniform("u_outside"), outside ? 1 : 0);
  glm::mat3 ndc_from_ray = glm::inverse(frame.atmo_ray_from_ndc);
  glUniformMatrix3fv(dome_program_.uniform("u_ndc_from_ray"), 1, GL_FALSE,
                     glm::value_ptr(ndc_from_ray));
  shade_only(kSkyPixel);
  // The mesh's rows are the rings (the first `rings` of them), and the
  // cells of a row its sectors of azimuth: only those in view are drawn, a
  // sixth of the dome's vertices and their sums from the ground; sector
  // by sector, so that each column of vertices serves the next sector too.
  const int segments = 2 * settings_.dome;
  std::vector<GLuint> dome_cells;
  for (glm::ivec2 run : visible_sectors(frame, up, east, north, segments)) {
    for (int segment = run.x; segment < run.y; ++segment) {
      for (int ring = 0; ring < rings; ++ring) add_cell(dome_cells, segments, segment, ring);
    }
  }
  draw_cells(dome_indices_, dome_vao_, dome_cells);
}

// The grid's pixels from its vertices, but for those the interpolation
// cannot serve, which sum their own rays. The grid's shader discards, so
// its stencil test comes after it: it runs on every pixel, but the heavy
// part is the vertices'.
void OneilTechnique::draw_grid(const SkyFrame& frame) {
  const int cell = settings_.cell;
  set_frame_uniforms(ground_program_, frame);
  glUniform1i(ground_program_.uniform("u_cell"), cell);
  glUniform1i(ground_program_.uniform("u_columns"), grid_width_);
  static_assert(kServedPixel == kGridPixel + 1);
  glStencilFunc(GL_EQUAL, kGridPixel, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  // Only the cells over the atmosphere: a surface beyond it, if any, is
  // left to the pixels' own rays, which see no air there.
  CellRange range = cells_of_sphere(frame, model_.top_radius, cell, grid_width_, grid_height_);
  std::vector<GLuint> grid_cells;
  for (int j = range.first.y; j < range.last.y; ++j) {
    for (int i = range.first.x; i < range.last.x; ++i) add_cell(grid_cells, grid_width_, i, j);
  }
  draw_cells(grid_indices_, grid_vao_, grid_cells);
}

void OneilTechnique::draw_own_rays(const SkyFrame& frame) {
  set_frame_uniforms(pixel_program_, frame);
  shade_only(kGridPixel);
  fullscreen_.draw();
}

}  // namespace planet
