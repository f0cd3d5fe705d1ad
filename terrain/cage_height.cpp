#include "terrain/cage_height.h"

#include "core/error.h"

#include <fmt/format.h>
#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace planet {

namespace {

using namespace OpenSubdiv;

constexpr int kN = CageHeight::kTableCells;

// A vertex position as OpenSubdiv's primvar refiner wants it.
struct Point {
  glm::dvec3 p{0.0};
  void Clear() { p = glm::dvec3(0.0); }
  void AddWithWeight(const Point& src, double w) { p += w * src.p; }
};

// OpenSubdiv reports what it rejects (and warns of) through callbacks that
// print "Error: ..." and "Warning: ..." on their own by default. They are
// caught here instead, for this thread's cage: an error becomes the reason
// in our one line, a warning is dropped (what it warns of is checked here
// before, or does not matter to a limit surface).
thread_local std::string t_opensubdiv_error;

extern "C" void on_opensubdiv_error(Far::ErrorType, const char* message) {
  if (!t_opensubdiv_error.empty()) t_opensubdiv_error += "; ";
  t_opensubdiv_error += message;
}

extern "C" void on_opensubdiv_warning(const char*) {}

std::unique_ptr<Far::TopologyRefiner> make_refiner(const ObjCage& cage, int level,
                                                   const std::string& name) {
  static const bool installed = [] {
    Far::SetErrorCallback(on_opensubdiv_error);
    Far::SetWarningCallback(on_opensubdiv_warning);
    return true;
  }();
  (void)installed;
  t_opensubdiv_error.clear();
  Far::TopologyDescriptor desc;
  desc.numVertices = int(cage.vertices.size());
  desc.numFaces = int(cage.face_sizes.size());
  desc.numVertsPerFace = cage.face_sizes.data();
  desc.vertIndicesPerFace = cage.face_indices.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, options)));
  if (!refiner || !t_opensubdiv_error.empty()) {
    std::string reason = t_opensubdiv_error.empty() ? "" : ": " + t_opensubdiv_error;
    t_opensubdiv_error.clear();
    throw InputError(
        fmt::format("{}: OpenSubdiv cannot build a Catmull-Clark cage from it{}", name, reason));
  }
  // Limit positions need the last level's full topology (its vertices'
  // neighbourhoods), which uniform refinement leaves out by default.
  Far::TopologyRefiner::UniformOptions uniform(level);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  return refiner;
}

// Limit points of the last level of a uniformly refined cage.
std::vector<Point> limit_of(const Far::TopologyRefiner& refiner, const ObjCage& cage) {
  std::vector<Point> levels(size_t(refiner.GetNumVerticesTotal()));
  for (size_t i = 0; i < cage.vertices.size(); ++i) levels[i].p = cage.vertices[i];
  Far::PrimvarRefinerReal<double> primvar(refiner);
  Point* src = levels.data();
  for (int l = 1; l <= refiner.GetMaxLevel(); ++l) {
    Point* dst = src + refiner.GetLevel(l - 1).GetNumVertices();
    primvar.Interpolate(l, src, dst);
    src = dst;
  }
  std::vector<Point> limit(size_t(refiner.GetLevel(refiner.GetMaxLevel()).GetNumVertices()));
  primvar.Limit(src, limit);
  return limit;
}

// Cube-map face f looks along +/- axis a = f / 2; (u, v) in [-1, 1] run
// along the next two axes, so that the grid direction is the gnomonic
// projection q = s e_a + u e_b + v e_c (unnormalised).
glm::dvec3 grid_direction(int face, int i, int j) {
  int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
  glm::dvec3 q(0.0);
  q[a] = face % 2 ? -1.0 : 1.0;
  q[b] = -1.0 + 2.0 * i / kN;
  q[c] = -1.0 + 2.0 * j / kN;
  return q;
}

double angle_between(const glm::dvec3& p, const glm::dvec3& q) {
  return std::atan2(glm::length(glm::cross(p, q)), glm::dot(p, q));
}

double& table_cell(std::vector<double>& table, int face, int i, int j) {
  return table[size_t((face * (kN + 1) + j) * (kN + 1) + i)];
}

// How far the flat faces of the refined mesh stray from the limit surface:
// each face of the level before the last splits into four, and its centre's
// limit point against the bilinear centre of its corners' limit points is
// that level's sag. Sag shrinks with the square of the face size, so the
// last level's is a quarter of it; half is taken for margin.
double refinement_sag(const Far::TopologyLevel& before, const std::vector<Point>& limit) {
  double sag = 0;
  for (int f = 0; f < before.GetNumFaces(); ++f) {
    auto fv = before.GetFaceVertices(f);
    glm::dvec3 mid(0.0);
    for (int k = 0; k < fv.size(); ++k) mid += limit[size_t(before.GetVertexChildVertex(fv[k]))].p;
    mid /= double(fv.size());
    sag = std::max(sag, glm::length(limit[size_t(before.GetFaceChildVertex(f))].p - mid));
  }
  return sag / 2.0;
}

// Rays from the centre through every grid direction, against one triangle
// of the refined mesh; each grid point keeps its outermost crossing. A
// triangle wholly in front of a face's plane projects to a triangle there
// (the gnomonic projection keeps straight lines), which bounds the grid
// points it can cover.
void cast_rays_at_triangle(std::vector<double>& table, const glm::dvec3& p0, const glm::dvec3& p1,
                           const glm::dvec3& p2) {
  for (int face = 0; face < 6; ++face) {
    int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
    double s = face % 2 ? -1.0 : 1.0;
    if (s * p0[a] <= 0 || s * p1[a] <= 0 || s * p2[a] <= 0) continue;
    double u_lo = 1e300, u_hi = -1e300, v_lo = 1e300, v_hi = -1e300;
    for (const glm::dvec3* p : {&p0, &p1, &p2}) {
      double u = (*p)[b] / (s * (*p)[a]), v = (*p)[c] / (s * (*p)[a]);
      u_lo = std::min(u_lo, u), u_hi = std::max(u_hi, u);
      v_lo = std::min(v_lo, v), v_hi = std::max(v_hi, v);
    }
    // A triangle that grazes the face's plane projects to coordinates of
    // any size (1e18 for the cube's limit): clamped to the grid before
    // they become ints, which cannot hold them (UBSan's finding).
    auto grid = [](double x) { return std::clamp((x + 1.0) * kN / 2.0, -1.0, kN + 1.0); };
    auto first = [&](double x) { return std::max(0, int(std::ceil(grid(x) - 1e-6))); };
    auto end = [&](double x) { return std::min(kN, int(std::floor(grid(x) + 1e-6))); };
    glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
    for (int j = first(v_lo); j <= end(v_hi); ++j) {
      for (int i = first(u_lo); i <= end(u_hi); ++i) {
        // Moller and Trumbore 1997: the ray t q against p0 + s e1 + t e2,
        // with a small tolerance so that no ray slips between triangles.
        glm::dvec3 q = grid_direction(face, i, j);
        glm::dvec3 pv = glm::cross(q, e2);
        double det = glm::dot(e1, pv);
        if (std::abs(det) < 1e-300) continue;
        glm::dvec3 tv = -p0;
        double bu = glm::dot(tv, pv) / det;
        glm::dvec3 qv = glm::cross(tv, e1);
        double bv = glm::dot(q, qv) / det;
        constexpr double kTol = 1e-7;
        if (bu < -kTol || bv < -kTol || bu + bv > 1.0 + kTol) continue;
        double t = glm::dot(e2, qv) / det;
        if (t <= 0) continue;
        double& r = table_cell(table, face, i, j);
        r = std::max(r, t * glm::length(q));  // the outermost crossing
      }
    }
  }
}

// Mean radius over the sphere of directions, each grid point weighted by its
// solid angle, du dv / (1 + u^2 + v^2)^(3/2) for the gnomonic map. A grid
// point no ray reached means the cage is not star-shaped about its centre.
double mean_radius(std::vector<double>& table, const std::string& name, bool about_origin) {
  double sum = 0, weight = 0;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j <= kN; ++j) {
      for (int i = 0; i <= kN; ++i) {
        double r = table_cell(table, face, i, j);
        if (r <= 0) {
          glm::dvec3 q = glm::normalize(grid_direction(face, i, j));
          throw InputError(fmt::format(
              "{}: the {} lies outside the cage's limit surface (the ray towards "
              "({:.3f}, {:.3f}, {:.3f}) meets no surface); the cage must be star-shaped about it",
              name, about_origin ? "origin" : "centroid", q.x, q.y, q.z));
        }
        double l = glm::length(grid_direction(face, i, j));
        double w = 1.0 / (l * l * l);
        sum += w * r;
        weight += w;
      }
    }
  }
  return sum / weight;
}

}  // namespace

std::vector<glm::dvec3> cage_limit_points(const ObjCage& cage, int level, const std::string& name) {
  auto refiner = make_refiner(cage, level, name);
  std::vector<glm::dvec3> out;
  for (const Point& p : limit_of(*refiner, cage)) out.push_back(p.p);
  return out;
}

CageHeight::CageHeight(const ObjCage& cage, const std::string& name, double body_radius,
                       std::vector<NoiseLayer> layers, std::optional<double> units_m)
    : body_radius_(body_radius), noise_(body_radius, std::move(layers), 0.0, std::nullopt) {
  // Refine until at least 5 x 10^4 faces: as fine as the table's 6 x 128^2 cells
  // on any reasonable cage, and at least once so that every face is a quad.
  int level = 1;
  while (level < 6 && double(cage.face_sizes.size()) * std::pow(4.0, level) < 5e4) ++level;
  auto refiner = make_refiner(cage, level, name);
  std::vector<Point> limit = limit_of(*refiner, cage);

  // A measured model's origin is its body's centre of mass, on the spin
  // axis; the limit points' centroid is not (Eros's 7790-plate model's
  // vertices average 0.33 km from it), and moving there would wobble the
  // turning body.
  glm::dvec3 centre(0.0);
  if (!units_m) {
    for (const Point& p : limit) centre += p.p;
    centre /= double(limit.size());
  }

  double chord_error = refinement_sag(refiner->GetLevel(level - 1), limit);
  table_.assign(size_t(6 * (kN + 1) * (kN + 1)), -1.0);
  const Far::TopologyLevel& last = refiner->GetLevel(level);
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    auto fv = last.GetFaceVertices(f);
    glm::dvec3 p0 = limit[size_t(fv[0])].p - centre;
    for (int k = 1; k + 1 < fv.size(); ++k) {
      cast_rays_at_triangle(table_, p0, limit[size_t(fv[k])].p - centre,
                            limit[size_t(fv[k + 1])].p - centre);
    }
  }

  double mean = mean_radius(table_, name, units_m.has_value());  // checks every ray met the cage
  scale_ = units_m ? *units_m : body_radius_ / mean;
  for (double& r : table_) r *= scale_;
  chord_error *= scale_;
  for (const Point& p : limit) limit_points_.push_back((p.p - centre) * scale_);

  double second = measure_table();
  // Bilinear interpolation of a C2 function misses it by at most
  // h^2 / 8 (max |f_uu| + max |f_vv|); h^2 f_uu is the second difference.
  // Doubled for margin, since the differences only sample the curvature;
  // the mesh's own sag adds.
  table_error_ = 2.0 * (second + second) / 8.0 + chord_error;

  HeightRange n = noise_.range();
  range_ = {min_radius_ - table_error_ - body_radius_ + n.min,
            max_radius_ + table_error_ - body_radius_ + n.max};
}

// Slope and curvature of the table per radian of direction, from the first
// and second differences between grid neighbours; returns the largest
// second difference along a grid line, metres.
double CageHeight::measure_table() {
  double second = 0;
  min_radius_ = 1e300, max_radius_ = 0;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j <= kN; ++j) {
      for (int i = 0; i <= kN; ++i) {
        double r = cell(face, i, j);
        min_radius_ = std::min(min_radius_, r);
        max_radius_ = std::max(max_radius_, r);
        glm::dvec3 q = grid_direction(face, i, j);
        for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
          if (i + di > kN || j + dj > kN) continue;
          double angle = angle_between(q, grid_direction(face, i + di, j + dj));
          double dr = cell(face, i + di, j + dj) - r;
          max_slope_ = std::max(max_slope_, std::abs(dr) / angle);
          if (i - di < 0 || j - dj < 0) continue;
          double d2 = cell(face, i + di, j + dj) - 2.0 * r + cell(face, i - di, j - dj);
          second = std::max(second, std::abs(d2));
          max_curvature_ = std::max(max_curvature_, std::abs(d2) / (angle * angle));
        }
      }
    }
  }
  return second;
}

double CageHeight::surface_radius(const glm::dvec3& d) const {
  glm::dvec3 m = glm::abs(d);
  int a = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  int b = (a + 1) % 3, c = (a + 2) % 3;
  int face = 2 * a + (d[a] < 0 ? 1 : 0);
  double x = (d[b] / m[a] + 1.0) * kN / 2.0, y = (d[c] / m[a] + 1.0) * kN / 2.0;
  int i = std::clamp(int(std::floor(x)), 0, kN - 1), j = std::clamp(int(std::floor(y)), 0, kN - 1);
  double fx = std::clamp(x - i, 0.0, 1.0), fy = std::clamp(y - j, 0.0, 1.0);
  return (1 - fy) * ((1 - fx) * cell(face, i, j) + fx * cell(face, i + 1, j)) +
         fy * ((1 - fx) * cell(face, i, j + 1) + fx * cell(face, i + 1, j + 1));
}

double CageHeight::height(const glm::dvec3& dir_body) const {
  return surface_radius(dir_body) - body_radius_ + noise_.height(dir_body);
}

HeightRange CageHeight::range_near(const glm::dvec3& dir_body, double radius) const {
  // A distance on the surface spans at most radius / min_radius of
  // direction. Inside a cell the bilinear table's gradient is a blend of
  // its edges' slopes, at most sqrt(2) times the steepest, and the
  // gnomonic cell is not quite square: a factor 2 covers both.
  double angle = radius / (min_radius_ - table_error_);
  double spread = 2.0 * max_slope_ * angle + table_error_;
  double h = surface_radius(dir_body) - body_radius_;
  HeightRange n = noise_.range_near(dir_body, radius);
  return {std::max(h - spread + n.min, range_.min), std::min(h + spread + n.max, range_.max)};
}

double CageHeight::interpolation_error(double spacing) const {
  // Linear interpolation over a step h misses by min(L h / 2, M h^2 / 8)
  // for slope L and curvature M of the smooth surface, plus twice the
  // table's own distance from that surface (once at the samples, once
  // between them).
  double angle = spacing / (min_radius_ - table_error_);
  double e = std::min(2.0 * max_slope_ * angle / 2.0,
                      max_curvature_ * angle * angle / 8.0 + 2.0 * table_error_);
  return e + noise_.interpolation_error(spacing);
}

}  // namespace planet
