// The asteroid's shape: OBJ cages, their Catmull-Clark limit surface, the
// direction -> radius table built from it, and every bad cage.
#include "terrain/cage_height.h"
#include "terrain/ground.h"
#include "terrain/obj_cage.h"
#include "terrain/terrain_config.h"
#include "terrain/terrain_surface.h"

#include "sim/free_flight.h"

#include <opensubdiv/far/error.h>

#include "core/data_paths.h"
#include "core/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <tuple>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::filesystem::path write_obj(const std::string& name, const std::string& text) {
  auto dir = std::filesystem::temp_directory_path() / "planet_cage_height_test";
  std::filesystem::create_directories(dir);
  auto file = dir / name;
  std::ofstream(file) << text;
  return file;
}

// The cube [-1, 1]^3, faces outward, with the face lines given (so that
// each test can vary the index forms or break one face).
std::string cube_obj(const std::vector<std::string>& faces) {
  std::string s;
  for (int i = 0; i < 8; ++i) {
    s += fmt::format("v {} {} {}\n", i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  }
  for (const std::string& f : faces) s += "f " + f + "\n";
  return s;
}
const std::vector<std::string> kCubeFaces = {"1 3 4 2", "5 6 8 7", "1 2 6 5",
                                             "3 7 8 4", "1 5 7 3", "2 4 8 6"};

// A sphere-like cage: a cube of n x n quads per face with its vertices
// pushed onto the unit sphere.
std::string sphere_obj(int n) {
  std::string v, f;
  std::map<std::tuple<int, int, int>, int> index;
  auto vid = [&](int x, int y, int z) {
    auto [it, inserted] = index.try_emplace({x, y, z}, int(index.size()) + 1);
    if (inserted) {
      glm::dvec3 p = glm::normalize(glm::dvec3(x, y, z));
      v += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
    }
    return it->second;
  };
  for (int a = 0; a < 3; ++a) {
    int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int s : {1, -1}) {
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          std::vector<int> q;
          for (auto [di, dj] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
            int g[3];
            g[a] = s * n, g[b] = 2 * (i + di) - n, g[c] = 2 * (j + dj) - n;
            q.push_back(vid(g[0], g[1], g[2]));
          }
          if (s < 0) std::swap(q[1], q[3]);
          f += fmt::format("f {} {} {} {}\n", q[0], q[1], q[2], q[3]);
        }
      }
    }
  }
  return v + f;
}

TEST(ObjCageTest, ReadsEveryIndexFormAndMergesSeams) {
  // The same cube with v, v/vt, v//vn, v/vt/vn and negative indices.
  std::string text = cube_obj({"1 3 4 2", "5/1 6/2 8/3 7/4", "1//1 2//1 6//1 5//1",
                               "3/1/1 7/1/1 8/1/1 4/1/1", "-8 -4 -2 -6", "2 4 8 6"});
  ObjCage cage =
      read_obj_cage(write_obj("forms.obj", "# comment\no cube\nvt 0 0\nvn 0 0 1\n" + text));
  EXPECT_EQ(cage.vertices.size(), 8u);
  ASSERT_EQ(cage.face_sizes.size(), 6u);
  EXPECT_EQ(cage.face_indices[16], 0);  // -8 of 8 vertices is the first
  EXPECT_EQ(cage.face_indices[17], 4);

  // A seam: vertex 9 repeats vertex 2 and one face uses it.
  std::string seam = cube_obj({"1 3 4 9", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6"});
  seam.insert(seam.find("f "), "v 1 -1 -1\n");
  EXPECT_EQ(read_obj_cage(write_obj("seam.obj", seam)).vertices.size(), 8u);
}

// Each bad cage gives an InputError naming the file, and the line where
// one line is at fault.
void expect_error(const std::string& name, const std::string& text, const std::string& what,
                  int line = 0) {
  auto file = write_obj(name, text);
  try {
    read_obj_cage(file);
    FAIL() << "accepted " << name;
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find(file.string()), std::string::npos) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
    if (line) {
      EXPECT_NE(m.find(fmt::format("{}:{}:", file.string(), line)), std::string::npos) << m;
    }
  }
}

TEST(ObjCageTest, BadCagesNameTheFileAndLine) {
  try {
    read_obj_cage("/nonexistent/cage.obj");
    FAIL() << "missing file accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/cage.obj"), std::string::npos);
  }
  expect_error("empty.obj", "", "no faces");
  expect_error("no_faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no faces");
  expect_error("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "not a finite number", 2);
  expect_error("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n", "not a finite number", 3);
  expect_error("range.obj", cube_obj({"1 3 4 2", "5 6 8 9"}), "out of range", 10);
  expect_error("negative.obj", cube_obj({"1 3 4 -9"}), "out of range", 9);
  expect_error("syntax.obj", cube_obj({"1 3 x 2"}), "not a vertex index", 9);
  // Three triangles on the edge from vertex 1 to vertex 2.
  expect_error("fan.obj",
               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\n"
               "f 1 2 3\nf 2 1 4\nf 1 2 5\n",
               "more than two faces", 8);
  std::vector<std::string> flipped = kCubeFaces;
  flipped[5] = "2 6 8 4";
  expect_error("flipped.obj", cube_obj(flipped), "not consistently oriented");
  std::vector<std::string> open = kCubeFaces;
  open.pop_back();
  expect_error("open.obj", cube_obj(open), "not closed");
}

TEST(CageHeightTest, CubeLimitIsTheKnownCatmullClarkLimit) {
  ObjCage cube = read_obj_cage(write_obj("cube.obj", cube_obj(kCubeFaces)));
  // Limit masks (Halstead et al. 1993), p = (n^2 v + 4 sum e + sum f) /
  // (n (n + 5)): a corner of valence 3 on the cage goes to (1/2, 1/2, 1/2);
  // a face centre is a regular vertex after one step with edge neighbours
  // at 3/4 and diagonal ones at 5/9 along the axis, so it goes to
  // (16 + 4 * 4 * 3/4 + 4 * 5/9) / 36 = 68/81.
  bool corner = false, centre = false;
  for (const glm::dvec3& p : cage_limit_points(cube, 2, "cube.obj")) {
    // Strictly inside the cage's convex hull.
    EXPECT_LT(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0);
    if (p.x > 0 && std::abs(p.x - p.y) < 1e-12 && std::abs(p.y - p.z) < 1e-12) {
      EXPECT_NEAR(p.x, 0.5, 1e-12);
      corner = true;
    }
    if (std::abs(p.x) < 1e-12 && std::abs(p.y) < 1e-12 && p.z > 0) {
      EXPECT_NEAR(p.z, 68.0 / 81.0, 1e-12);
      centre = true;
    }
  }
  EXPECT_TRUE(corner);
  EXPECT_TRUE(centre);

  // Scaled to a body of radius 1000 m: by symmetry the corners' and the
  // faces' radii keep their ratio.
  CageHeight h(cube, "cube.obj", 1000.0, {});
  double r_face = h.surface_radius({0, 0, 1}),
         r_corner = h.surface_radius(glm::normalize(glm::dvec3(1)));
  EXPECT_NEAR(r_corner / r_face, (std::sqrt(3.0) / 2.0) / (68.0 / 81.0), 1e-3);
  EXPECT_NEAR(h.surface_radius({0, -1, 0}), r_face, 1e-6);
}

TEST(CageHeightTest, SphereLikeCageGivesNearlyConstantRadius) {
  ObjCage sphere = read_obj_cage(write_obj("sphere.obj", sphere_obj(6)));
  CageHeight h(sphere, "sphere.obj", 30000.0, {});
  // The limit surface of a cage on a sphere lies a little inside it, more
  // between cage vertices than at them, and the cube's corners (valence 3)
  // flatten it most: within 1.5 % of the radius for 6 x 6 quads a face.
  EXPECT_GT(h.range().min, -450.0);
  EXPECT_LT(h.range().max, 450.0);
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  double sum = 0;
  for (int k = 0; k < 1000; ++k) {
    glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    EXPECT_NEAR(h.height(d), 0.0, 450.0);
    sum += h.height(d);
  }
  EXPECT_NEAR(sum / 1000, 0.0, 30.0);  // the mean radius is the body's
}

TEST(CageHeightTest, TableAgreesWithDirectLimitEvaluation) {
  ObjCage cage = read_obj_cage(project_root() / "data/shapes/asteroid.obj");
  CageHeight h(cage, "asteroid.obj", 30000.0, {});
  EXPECT_GT(h.table_error(), 0.0);
  EXPECT_LT(h.table_error(), 50.0);  // well under a tile's error at the levels that matter
  double worst = 0;
  for (const glm::dvec3& p : h.limit_points()) {
    double r = glm::length(p);
    worst = std::max(worst, std::abs(h.surface_radius(p / r) - r));
  }
  EXPECT_LE(worst, h.table_error());
  EXPECT_GT(worst, 0.0);

  // range_near holds every height around a direction, and range() every
  // height at all; the linear interpolation between two points a spacing
  // apart stays within interpolation_error of the surface between them.
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 300; ++k) {
    glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    glm::dvec3 t = glm::normalize(glm::cross(d, glm::dvec3(g(rng), g(rng), g(rng))));
    double radius = 2000.0;
    HeightRange near = h.range_near(d, radius);
    for (int s = -4; s <= 4; ++s) {
      glm::dvec3 e = glm::normalize(d + t * (s * radius / 4.0 / 36000.0));
      double he = h.height(e);
      EXPECT_GE(he, near.min);
      EXPECT_LE(he, near.max);
      EXPECT_GE(he, h.range().min);
      EXPECT_LE(he, h.range().max);
    }
    double spacing = 500.0;
    glm::dvec3 a = glm::normalize(d - t * (spacing / 2 / 30000.0));
    glm::dvec3 b = glm::normalize(d + t * (spacing / 2 / 30000.0));
    double mid = h.height(glm::normalize(a + b));
    EXPECT_NEAR(mid, (h.height(a) + h.height(b)) / 2, h.interpolation_error(spacing));
  }
}

TEST(CageHeightTest, AsteroidBodyFileUsesTheCage) {
  Body body;
  body.name = "Test";
  body.file = "bodies/test.json";
  body.shape.equatorial_radius = 30000.0;
  body.terrain = nlohmann::json::parse(R"({"height": {"type": "cage", "file":
      "data/shapes/asteroid.obj", "layers": [{"type": "fbm", "amplitude_m": 100,
      "wavelength_m": 5000, "octaves": 3}]}})");
  TerrainConfig config = parse_terrain(body);
  HeightRange r = config.heights->range();
  // A potato: its radius varies by several km either side of the mean.
  EXPECT_LT(r.min, -3000.0);
  EXPECT_GT(r.max, 3000.0);

  body.terrain =
      nlohmann::json::parse(R"({"height": {"type": "cage", "file": "/nonexistent/shape.obj"}})");
  try {
    parse_terrain(body);
    FAIL() << "missing cage accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/shape.obj"), std::string::npos);
  }
}

// The pilot over the asteroid counts heights from its ground, the cage's
// limit surface displaced by its noise, wherever that lies against the
// ellipsoid: fly's start 30 m above the ground over the Alps' latitude and
// longitude, where the ground lies 307 m inside the ellipsoid, was held at
// the ellipsoid, 307.7 m above the ground (issue 62, point 3).
TEST(CageHeightTest, ThePilotOverTheAsteroidCountsFromItsGround) {
  Body body = load_body(find_body_file("asteroid"));
  TerrainSurface surface(body.shape, parse_terrain(body));
  Geodesy geodesy(body.shape);
  auto ground = [&](const Geodetic& g) { return ground_height(surface, geodesy, g); };
  Geodetic place{glm::radians(46.55), glm::radians(7.98), 0.0};
  const double below = ground(place);
  ASSERT_LT(below, -100.0) << "the test wants a place whose ground lies inside the ellipsoid";
  // The ground point is where the drawn surface (its height source along
  // the direction) lies.
  glm::dvec3 p = ground_point(surface, geodesy, place);
  EXPECT_NEAR(glm::length(p), 30000.0 + surface.heights().height(glm::normalize(p)), 1e-6);

  place.height = below + 30.0;
  FreeFlight flight(body, place, 0.0);
  flight.set_ground(ground);
  EXPECT_NEAR(flight.height_above_ground(), 30.0, 1e-6);
  // Straight down at ten times the speed: held at the clearance above that
  // ground, nowhere near the ellipsoid.
  FlightInput down;
  down.move = {0, -1, 0};
  down.boost = 10.0;
  for (int i = 0; i < 240; ++i) flight.step(1.0 / 120.0, 0.0, down);
  EXPECT_NEAR(flight.height_above_ground(), FreeFlight::kClearance, 1e-6);
  EXPECT_NEAR(geodesy.geodetic_from_body(flight.camera().pos_body).height,
              below + FreeFlight::kClearance, 1e-3);
}

// Real shape models (4 Vesta, 243 Ida, 951 Gaspra), where Debian's
// stellarium-data installs them: every OBJ there must load as a cage.
TEST(CageHeightTest, StellariumModelsLoadAsCages) {
  std::filesystem::path dir = "/usr/share/stellarium/models";
  int loaded = 0;
  if (std::filesystem::is_directory(dir)) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() != ".obj") continue;
      SCOPED_TRACE(entry.path().string());
      CageHeight h(read_obj_cage(entry.path()), entry.path().string(), 10000.0, {});
      EXPECT_LT(h.range().min, 0.0);
      EXPECT_GT(h.range().max, 0.0);
      EXPECT_TRUE(std::isfinite(h.height({0, 0, 1})));
      ++loaded;
    }
  }
  if (loaded == 0) GTEST_SKIP() << "no shape models in " << dir;
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// OpenSubdiv prints "Error: ..." and "Warning: ..." itself unless told
// otherwise: once a cage is built, what it reports goes into our own one
// line instead, and nothing of it reaches the terminal.
TEST(CageHeightTest, OpenSubdivPrintsNothingOfItsOwn) {
  ObjCage cube = read_obj_cage(write_obj("cube.obj", cube_obj(kCubeFaces)));
  cage_limit_points(cube, 1, "cube.obj");
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  OpenSubdiv::Far::Warning("a warning of OpenSubdiv's");
  OpenSubdiv::Far::Error(OpenSubdiv::Far::FAR_RUNTIME_ERROR, "an error of OpenSubdiv's");
  std::string out = testing::internal::GetCapturedStdout();
  std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out + err, "");
  // And the next cage starts clean.
  EXPECT_NO_THROW(cage_limit_points(cube, 1, "cube.obj"));
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
