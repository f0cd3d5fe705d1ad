// In lowlands and hollows the ground lies below the atmosphere's bottom
// sphere, and every technique lifts the camera onto the sphere. Rays that
// pass over the terrain's silhouette but dip below the lifted camera's
// horizon met the sphere: a ground the terrain does not have, drawn as a
// dark line along the horizon (1-2 px, 43 % darker than the sky above it in
// `terrain_mars` with bruneton). Every technique now shows the sky there.
#include "atmosphere/atmosphere_space.h"
#include "atmosphere/gpu/registry.h"
#include "core/data_paths.h"
#include "gl/context.h"
#include "render/frame.h"
#include "sim/geodesy.h"
#include "terrain/ground.h"
#include "terrain/terrain_config.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

constexpr int kWidth = 96, kHeight = 54;
// A narrow field, so that a pixel spans little of the sky's gradient at
// the horizon (0.19 deg).
constexpr double kFovDeg = 10.0;

struct Lowland {
  const char* body;
  Geodetic place;  // the camera, 2 m over the ground
  std::vector<double> headings_deg;
};

// Where the terrain's silhouette can fall below the lifted camera's
// horizon: the lowest place of a 2-degree grid (70 S to 70 N) below the
// sphere from which a level ray clears the ground ahead in some heading
// (the ground falls away faster than the sphere curves). The lowest places
// themselves are crater floors, walled in above the sphere.
// Mars is the procedural one: its noise leaves open lowlands below the
// sphere, where MOLA's lowest open plains found no view below the horizon.
std::filesystem::path body_file(const std::string& name) {
  if (name == "mars") return project_root() / "tests/data/planets/mars_procedural.json";
  return data_dir() / "planets" / (name + ".json");
}

Lowland open_lowland(const char* name) {
  Body body = load_body(body_file(name));
  TerrainSurface surface(body.shape, parse_terrain(body));
  Geodesy geodesy(body.shape);
  const double radius = body.shape.equatorial_radius;
  const double highest = surface.heights().range().max;
  std::vector<Geodetic> places;
  for (int lat = -70; lat <= 70; lat += 2) {
    for (int lon = -180; lon < 180; lon += 2) {
      Geodetic place{glm::radians(double(lat)), glm::radians(double(lon)), 0.0};
      place.height = ground_height(surface, geodesy, place) + 2.0;
      if (place.height < -100.0) places.push_back(place);
    }
  }
  std::sort(places.begin(), places.end(),
            [](const Geodetic& a, const Geodetic& b) { return a.height < b.height; });
  for (const Geodetic& place : places) {
    const double r = radius + place.height;
    // The level ray passes over the place at central angle delta at
    // r / cos(delta); past delta_end it is above the highest ground.
    const double delta_end = std::acos(std::min(1.0, r / (radius + highest)));
    std::vector<double> clear;
    for (int heading = 0; heading < 360; heading += 15) {
      const double bearing = glm::radians(double(heading));
      bool blocked = false;
      for (int k = 1; k <= 200 && !blocked; ++k) {
        const double delta = delta_end * k / 200.0;
        const double lat = std::asin(std::sin(place.lat) * std::cos(delta) +
                                     std::cos(place.lat) * std::sin(delta) * std::cos(bearing));
        const double lon =
            place.lon + std::atan2(std::sin(bearing) * std::sin(delta) * std::cos(place.lat),
                                   std::cos(delta) - std::sin(place.lat) * std::sin(lat));
        const double ground = ground_height(surface, geodesy, {lat, lon, 0.0});
        blocked = radius + ground > r / std::cos(delta) - 1.0;
      }
      if (!blocked) clear.push_back(double(heading));
    }
    if (!clear.empty()) return {name, place, clear};
  }
  ADD_FAILURE() << name << ": no place below the sphere looks over open ground";
  return {name, {}, {}};
}

// Over Mars's northern lowlands where `terrain_mars` starts (748 m below
// the sphere), and over the lowest open lowland of Mars and of the
// asteroid (Earth's ground never lies below its sea, the sphere). Level
// views: each open pixel whose ray dips below the lifted camera's
// horizon must show about the sky of the open pixel just above it.
TEST(LiftedHorizonGLTest, NoLineWhereTheGroundMeetsTheAirOverTheLowestGround) {
  auto context = GlContext::create_headless();
  std::vector<Lowland> lowlands = {
      {"mars", {glm::radians(18.65), glm::radians(-134.8), -747.912}, {0, 90, 180, 270}}};
  for (const char* name : {"mars", "asteroid"}) lowlands.push_back(open_lowland(name));
  // Pixels below the lifted horizon seen on each body: there must be some,
  // or the test shows nothing. (The searched places hold few or many of
  // them by a metre of relief: 7 pixels at Mars's -2418 m in one build, 0
  // at its -2173 m in a clang build.)
  std::map<std::string, int> raised_on;
  for (const Lowland& lowland : lowlands) {
    Body body = load_body(body_file(lowland.body));
    AtmosphereModel model = load_atmosphere(body);
    const glm::dvec3 scale = atmosphere_scale(body.shape, model.bottom_radius);
    const double r_lifted = model.bottom_radius + 1.0;
    const double mu_horizon = -std::sqrt(1.0 - std::pow(model.bottom_radius / r_lifted, 2));
    // One renderer for the place, so that its tiles load once.
    FrameRenderer renderer(kWidth, kHeight);
    FrameOptions options;
    options.terrain_wait_s = 120.0;
    renderer.set_options(options);
    bool first = true;
    for (const TechniqueEntry& entry : technique_registry()) {
      std::string technique = entry.name + ":" + entry.quality_points.front().first;
      if (first) {
        renderer.set_body(body, model, make_technique(technique));
        first = false;
      } else {
        std::unique_ptr<AtmosphereTechnique> next = make_technique(technique);
        next->update(model);
        renderer.swap_technique(std::move(next));
      }
      int raised = 0;
      double worst = 0.0;
      for (double heading : lowland.headings_deg) {
        auto view = view_from_place(body.shape, lowland.place, heading, 0.0, kFovDeg, 20.0,
                                    heading + 60.0);
        renderer.render(view.camera, view.sun_dir_body, 10.0);
        std::vector<float> hdr = renderer.read_hdr();
        std::vector<float> distance = renderer.read_distance(view.camera);
        const glm::dvec3 up = glm::normalize(scale * view.camera.pos_body);
        ASSERT_LT(glm::length(scale * view.camera.pos_body), model.bottom_radius)
            << lowland.body << ": the camera is not below the sphere";
        const glm::dmat3 ray_from_ndc =
            atmo_ray_from_ndc(scale, view.camera, double(kWidth) / kHeight);
        for (int x = 0; x < kWidth; ++x) {
          for (int y = 0; y + 1 < kHeight; ++y) {  // rows bottom-up
            auto at = [&](int row) { return size_t(row) * kWidth + size_t(x); };
            if (!std::isinf(distance[at(y)]) || !std::isinf(distance[at(y + 1)])) continue;
            glm::dvec2 ndc((x + 0.5) / kWidth * 2.0 - 1.0, (y + 0.5) / kHeight * 2.0 - 1.0);
            double mu = glm::dot(glm::normalize(ray_from_ndc * glm::dvec3(ndc, 1.0)), up);
            if (mu >= mu_horizon + 1e-3) continue;
            ++raised;
            for (int c = 0; c < 3; ++c) {
              double above = hdr[at(y + 1) * 4 + size_t(c)], here = hdr[at(y) * 4 + size_t(c)];
              double error = std::abs(here - above) / above;
              worst = std::max(worst, error);
              EXPECT_LT(error, 0.1) << technique << " over " << lowland.body << " heading "
                                    << heading << ", pixel " << x << ", " << y << " channel "
                                    << c << ": " << here << " under a sky of " << above;
            }
          }
        }
      }
      raised_on[lowland.body] += raised;
      std::printf("%-20s %-8s at %6.2f, %7.2f deg, %7.1f m: %3d pixels below the lifted horizon, worst %.2f %% "
                  "off the sky above\n",
                  technique.c_str(), lowland.body, glm::degrees(lowland.place.lat),
                  glm::degrees(lowland.place.lon), lowland.place.height, raised, 100.0 * worst);
    }
  }
  for (const char* body : {"mars", "asteroid"}) {
    EXPECT_GT(raised_on[body], 0) << body << ": no view looked below the lifted horizon";
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
