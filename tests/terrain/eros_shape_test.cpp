// 433 Eros, the real asteroid: its shape model as the terrain loads it
// (size, frame), its rotation from the IAU's elements, and every bad shape
// file refused in one line naming it.
#include "terrain/cage_height.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"
#include "terrain/terrain_surface.h"
#include "terrain/tile_mesh.h"

#include "sim/body.h"
#include "sim/flight_script.h"
#include "sim/geodesy.h"

#include "core/data_paths.h"
#include "core/error.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

Body eros_body() { return load_body(find_body_file("eros")); }

std::shared_ptr<const CageHeight> eros_cage(const Body& body) {
  auto cage = std::dynamic_pointer_cast<const CageHeight>(parse_terrain(body).heights);
  if (!cage) throw std::runtime_error("eros.json's terrain is not a cage");
  return cage;
}

// The extent of points along a unit direction: the distance between the
// two planes at right angles to it that hold them all between them.
double extent(const std::vector<glm::dvec3>& points, const glm::dvec3& dir) {
  double lo = 1e300, hi = -1e300;
  for (const glm::dvec3& p : points) {
    lo = std::min(lo, glm::dot(p, dir));
    hi = std::max(hi, glm::dot(p, dir));
  }
  return hi - lo;
}

// The size as drawn: the limit surface of the plate model, in metres, in
// the model's own frame. The plate model itself measures 32.87 km along its
// long axis (in the equator, 173 deg E), 15.10 km across it in the
// equator and 11.95 km along the pole, and holds 2526 km^3 (data/shapes/
// eros/SOURCE.md); the limit surface lies a little inside the plates where
// they bend (Catmull-Clark shrinks a triangle mesh's ridges), measured here
// 32.84 x 15.09 x 11.92 km and 2521 km^3. The bounds: each extent within
// 1 % of the plates' (ten times the shrink, a quarter of the 4 % that a
// fit to the body's radius would make), and the volume within 1.5 % of
// Thomas et al. 2002's 2503 +/- 25 km^3. The often quoted "34.4 x 11.2 x
// 11.2 km" are not extents of this model (nor of the finer ones, whose
// largest radius is 17.7 km as here), so the test holds to the model.
TEST(ErosShapeTest, SizeIsThePlateModelsInKilometres) {
  Body body = eros_body();
  auto cage = eros_cage(body);
  EXPECT_DOUBLE_EQ(cage->scale(), 1000.0);
  const std::vector<glm::dvec3>& points = cage->limit_points();

  // The long axis lies in the equator (the model's principal axis of
  // inertia is 0.13 deg from it), 7 deg from the -X axis: the widest
  // extent there.
  double longest = 0, longest_angle = 0;
  for (int i = 0; i < 3600; ++i) {
    double a = glm::pi<double>() * i / 3600.0;
    double e = extent(points, {std::cos(a), std::sin(a), 0.0});
    if (e > longest) longest = e, longest_angle = a;
  }
  double across = extent(points, {-std::sin(longest_angle), std::cos(longest_angle), 0.0});
  double polar = extent(points, {0.0, 0.0, 1.0});
  EXPECT_NEAR(longest / 1000.0, 32.87, 0.33);
  EXPECT_NEAR(across / 1000.0, 15.10, 0.15);
  EXPECT_NEAR(polar / 1000.0, 11.95, 0.12);
  EXPECT_NEAR(glm::degrees(longest_angle), 173.0, 1.0);

  // The volume the table encloses, over a Fibonacci lattice of directions:
  // V = sum of r^3 / 3 over equal solid angles.
  const int n = 40000;
  double volume = 0;
  for (int i = 0; i < n; ++i) {
    double z = 1.0 - (2.0 * i + 1.0) / n, s = std::sqrt(1.0 - z * z);
    double phi = i * glm::pi<double>() * (3.0 - std::sqrt(5.0));
    double r = cage->surface_radius({s * std::cos(phi), s * std::sin(phi), z});
    volume += r * r * r / 3.0;
  }
  volume *= 4.0 * glm::pi<double>() / n;
  EXPECT_NEAR(volume / 1e9, 2503.0, 0.015 * 2503.0);
  std::printf("Eros as drawn: %.2f x %.2f x %.2f km, %.0f km^3 (long axis at %.1f deg east)\n",
              longest / 1000.0, across / 1000.0, polar / 1000.0, volume / 1e9,
              glm::degrees(longest_angle));
}

// The model keeps its own origin, the centre of mass on the spin axis: the
// radii along the frame's axes are the plate model's own, cast from its
// origin (14.29 km towards +X, 17.31 towards -X, 5.85 and 3.50 along +/-Y,
// 5.39 and 5.91 along +/-Z). Fitted about its vertices' centroid instead,
// as the artistic asteroid is, the X radii would move by 0.3 km.
TEST(ErosShapeTest, KeepsTheModelsOriginAndAxes) {
  auto cage = eros_cage(eros_body());
  const struct {
    glm::dvec3 dir;
    double km;
  } radii[] = {{{1, 0, 0}, 14.2937}, {{-1, 0, 0}, 17.3083}, {{0, 1, 0}, 5.8506},
               {{0, -1, 0}, 3.4991}, {{0, 0, 1}, 5.3876},   {{0, 0, -1}, 5.9096}};
  for (const auto& r : radii) {
    // 60 m: the limit surface's shrink where the plates bend, measured at
    // most 35 m along these six.
    EXPECT_NEAR(cage->surface_radius(r.dir) / 1000.0, r.km, 0.06)
        << "along (" << r.dir.x << ", " << r.dir.y << ", " << r.dir.z << ")";
  }
}

// The IAU's elements for Eros (Archinal et al. 2018): pole at RA 11.35 deg,
// Dec 17.22 deg, W = 326.07 deg + 1639.38864745 deg/day: a sidereal period
// of 5.270257 h, 18972.926 s.
TEST(ErosShapeTest, RotationIsTheIauElements) {
  Body body = eros_body();
  ASSERT_TRUE(body.has_rotation);
  EXPECT_NEAR(body.rotation.sidereal_period, 360.0 / 1639.38864745 * 86400.0, 0.01);
  EXPECT_NEAR(body.rotation.sidereal_period / 3600.0, 5.270257, 1e-6);
  EXPECT_NEAR(glm::degrees(body.rotation.angle(0.0)), 326.07, 1e-9);
  // A day later W has turned 1639.38864745 deg: 4.553857 turns and a bit.
  double w = glm::degrees(body.rotation.angle(86400.0));
  EXPECT_NEAR(std::fmod(w - 326.07 + 720.0, 360.0), std::fmod(1639.38864745, 360.0), 1e-4);
  // The pole's ICRF direction is the body frame's +Z at any time.
  double ra = glm::radians(11.35), dec = glm::radians(17.22);
  glm::dvec3 pole_icrf(std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec));
  for (double t : {0.0, 1e4, 8.3e8}) {
    glm::dvec3 z =
        body.rotation.body_from_inertial(t) * (body.rotation.inertial_from_icrf() * pole_icrf);
    EXPECT_NEAR(z.z, 1.0, 1e-12) << "at t = " << t;
  }
  EXPECT_FALSE(body.has_atmosphere());
}

// A tile's skirts hang inside the body. Over Eros the crack bound they are
// sized by reaches tens of km on the coarse levels (its walls are steep
// against its sphere); hung to that depth they passed the centre and came
// out of the far side, a sheet over the ground in front that hid every
// part of the body below its 8.42 km sphere. Each skirt vertex must stay on
// its edge vertex's side of the centre and under the ground there.
TEST(ErosShapeTest, SkirtsStayInsideTheBody) {
  Body body = eros_body();
  TerrainSurface surface(body.shape, parse_terrain(body));
  for (int level : {0, 1, 2}) {
    for (int face = 0; face < 6; ++face) {
      TileKey key{face, level, 0, 0};
      TileMesh tile = build_tile(surface, key);
      const int n = kTileGrid;
      for (size_t k = size_t(n * n); k < tile.vertices.size(); ++k) {
        glm::dvec3 p = tile.center_body + glm::dvec3(tile.vertices[k].offset);
        double ground = glm::length(surface.point(glm::normalize(p)));
        ASSERT_LT(glm::length(p), ground + 1.0) << key.name() << " skirt vertex " << k;
        ASSERT_GT(glm::dot(p, tile.center_body), 0.0) << key.name() << " skirt vertex " << k;
      }
    }
  }
}

// The shipped landing (data/flights/eros_landing.json) comes down into the
// saddle on Eros's concave side, whose floor lies 4.44 km under the 8.42 km
// sphere, deeper than half its radius (the bound on keyframes' heights
// before): every frame, not only the keyframes, stays above the ground,
// and the last stands 2 m over it in daylight.
TEST(ErosShapeTest, TheLandingStaysAboveTheSaddlesFloor) {
  FlightScript script =
      load_flight_script(data_dir() / "flights" / "eros_landing.json", terrain_ground());
  FlightPath path(script);
  GroundHeight ground = terrain_ground();
  for (int i = 0; i < script.frame_count(); ++i) {
    Geodetic g = path.place_at(script.frame_time(i));
    double clearance = g.height - ground(script.body, g);
    EXPECT_GT(clearance, 1.0) << "frame " << i;
  }
  Geodetic last = path.place_at(script.duration());
  double floor = ground(script.body, last);
  EXPECT_LT(floor, -0.5 * script.body.shape.polar_radius());
  EXPECT_NEAR(last.height - floor, 2.0, 1e-6);
  // The sun over the sphere's horizon there (the ground's own slope aside).
  glm::dvec3 up = Geodesy(script.body.shape).body_from_enu(last)[2];
  EXPECT_GT(glm::dot(path.sun_dir_at(script.duration()), up), 0.2);
}

// A broken copy of the shape file, behind a body that names it: refused
// with one line that names the file (and what is wrong with it).
std::string error_for(const std::string& shape_text, const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "planet_eros_shape_test";
  std::filesystem::create_directories(dir);
  auto file = dir / name;
  if (!shape_text.empty()) std::ofstream(file, std::ios::binary) << shape_text;
  Body body = eros_body();
  body.terrain["height"]["file"] = file.string();
  try {
    parse_terrain(body);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ErosShapeTest, BadShapeFilesAreRefusedInOneLineNamingTheFile) {
  std::ifstream in(project_root() / "data/shapes/eros/eros007790.obj", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(text.size(), 300000u);

  auto expect_refused = [](const std::string& message, const std::string& name,
                           const std::string& what) {
    SCOPED_TRACE(message);
    EXPECT_NE(message.find(name), std::string::npos) << "does not name the file";
    EXPECT_NE(message.find(what), std::string::npos) << "does not say what is wrong";
    EXPECT_EQ(message.find('\n'), std::string::npos) << "more than one line";
  };
  expect_refused(error_for("", "missing.obj"), "missing.obj", "cannot read");
  // Cut in the middle of a vertex line, and in the middle of the faces.
  std::string cut_vertex = text.substr(0, text.find("\nv", 1000) + 10);
  expect_refused(error_for(cut_vertex, "cut_vertex.obj"), "cut_vertex.obj",
                 "needs three coordinates");
  std::string cut_faces = text.substr(0, text.rfind('\n', text.size() * 4 / 5) + 1);
  ASSERT_NE(cut_faces.find("\nf "), std::string::npos);
  expect_refused(error_for(cut_faces, "cut_faces.obj"), "cut_faces.obj", "not closed");
  std::string no_faces = text.substr(0, text.find("\nf ") + 1);
  expect_refused(error_for(no_faces, "no_faces.obj"), "no_faces.obj", "no faces");
  // A NaN in the first vertex, as a broken converter would write it.
  std::string nan = text;
  size_t v = nan.find("v   -1.75999E+01");
  ASSERT_NE(v, std::string::npos);
  nan.replace(v, 16, "v   nan");
  expect_refused(error_for(nan, "nan_vertex.obj"), "nan_vertex.obj", "not a finite number");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
