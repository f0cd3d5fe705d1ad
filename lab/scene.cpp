#include "lab/scene.h"

#include "atmosphere/atmosphere_space.h"
#include "atmosphere/math/shared_math.h"
#include "core/error.h"
#include "core/hash.h"
#include "sim/eclipse.h"
#include "sim/ephemeris.h"
#include "sim/geodesy.h"

#include <fmt/format.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtx/matrix_operation.hpp>

namespace planet {

uint64_t Scene::seed() const { return fnv1a(name); }

namespace {

using Placement = ScenePlacement;

Scene make_scene(std::string name, std::string description, std::string body_name,
                 const Placement& p, double exposure) {
  Scene s;
  s.name = std::move(name);
  s.description = std::move(description);
  s.body = std::move(body_name);
  s.exposure = exposure;
  return placed(std::move(s), p);
}

}  // namespace

Scene placed(Scene s, const ScenePlacement& p) {
  Body body = scene_body(s);
  Geodesy geodesy(body.shape);
  Geodetic place{glm::radians(p.lat_deg), glm::radians(p.lon_deg), p.height_m};
  s.camera = geodesy.camera_at(place, glm::radians(p.heading_deg), glm::radians(p.pitch_deg),
                               glm::radians(p.vertical_fov_deg));
  s.sun_dir_body = glm::normalize(geodesy.body_direction(place, glm::radians(p.sun_elevation_deg),
                                                         glm::radians(p.sun_azimuth_deg)));
  return s;
}

std::vector<Scene> canonical_scenes() {
  // Ground skies: a 90 degree vertical field (127 degrees across at 2:1)
  // pitched up so that the horizon and most of the sky are in view.
  Placement ground{45.0, 0.0, 2.0, 0.0, 35.0, 90.0, 60.0, 30.0};
  std::vector<Scene> scenes;
  scenes.push_back(make_scene("earth_noon", "Earth from the ground, sun 60 deg up, in view",
                              "earth", ground, 10.0));
  Placement sunset = ground;
  sunset.pitch_deg = 30.0;
  sunset.sun_elevation_deg = 2.0;
  sunset.sun_azimuth_deg = 0.0;
  scenes.push_back(make_scene("earth_sunset", "Earth from the ground, facing the sun 2 deg up",
                              "earth", sunset, 20.0));
  Placement twilight = sunset;
  twilight.sun_elevation_deg = -5.0;
  twilight.sun_azimuth_deg = 180.0;
  scenes.push_back(make_scene("earth_twilight",
                              "Earth from the ground, sun 5 deg below the horizon behind the "
                              "camera: the planet's shadow on the eastern sky",
                              "earth", twilight, 200.0));
  // From 400 km the limb is 19.7 deg below the horizontal (cos = R / (R + h))
  // and the atmosphere's top 17.4 deg: a narrow field shows the layer.
  Placement orbit{0.0, 0.0, 400e3, 90.0, -18.5, 10.0, 20.0, 150.0};
  scenes.push_back(make_scene("earth_400km", "Earth's limb from 400 km, sun to the right", "earth",
                              orbit, 10.0));
  Placement far{0.0, 0.0, 40000e3, 0.0, -90.0, 20.0, 30.0, 90.0};
  scenes.push_back(make_scene("earth_40000km", "the whole Earth from 40 000 km, lit from the east",
                              "earth", far, 10.0));
  Placement mars = ground;
  mars.lat_deg = 20.0;
  scenes.push_back(
      make_scene("mars_noon", "Mars from the ground, sun 60 deg up", "mars", mars, 10.0));
  Placement mars_sunset = sunset;
  mars_sunset.lat_deg = 20.0;
  mars_sunset.pitch_deg = 20.0;
  scenes.push_back(make_scene("mars_sunset", "Mars from the ground, facing the sun 2 deg up",
                              "mars", mars_sunset, 20.0));
  Placement rock = ground;
  rock.sun_elevation_deg = 40.0;
  scenes.push_back(make_scene("asteroid_surface", "the asteroid's sky from its surface", "asteroid",
                              rock, 10.0));
  Placement rock_space{0.0, 0.0, 70e3, 0.0, -90.0, 60.0, 30.0, 90.0};
  scenes.push_back(make_scene("asteroid_space", "the asteroid and its atmosphere from 70 km",
                              "asteroid", rock_space, 10.0));
  // Variants of Earth noon that stress the techniques.
  auto noon_variant = [&](const char* name, const char* description) {
    Scene v = scenes[0];
    v.name = name;
    v.description = description;
    return v;
  };
  Scene dense10 = noon_variant("earth_noon_dense10", "earth_noon with 10x the scattering");
  dense10.scattering_scale = 10.0;
  dense10.exposure = 5.0;
  scenes.push_back(dense10);
  Scene dense50 = noon_variant("earth_noon_dense50", "earth_noon with 50x the scattering");
  dense50.scattering_scale = 50.0;
  dense50.exposure = 5.0;
  scenes.push_back(dense50);
  Scene forward = noon_variant("earth_noon_g095", "earth_noon with Mie asymmetry g = 0.95");
  forward.mie_g = 0.95;
  scenes.push_back(forward);
  return scenes;
}

namespace {

double sun_share(const Scene& scene, double sun_radius, const glm::dvec3& pos_body) {
  if (scene.moon_radius <= 0.0) return 1.0;
  return shared::occluded_sun_fraction(scene.sun_dir_body, sun_radius,
                                       scene.moon_pos_body - pos_body, scene.moon_radius)
      .g;
}

}  // namespace

double scene_sun_share(const Scene& scene, const glm::dvec3& pos_body) {
  return sun_share(scene, load_atmosphere(scene_body(scene)).sun_angular_radius, pos_body);
}

std::vector<Scene> eclipse_scenes() {
  const EclipseConstants constants;
  UtcSeconds utc = solar_eclipse(parse_utc("2024-04-08T18:00:00Z", "eclipse scene"))->greatest;
  std::optional<SolarEclipse> eclipse = solar_eclipse(utc);
  glm::dmat3 itrs = itrs_from_gcrs(utc);
  glm::dvec3 sun_body = itrs * sun_pos_gcrs(utc);
  Scene total;
  total.name = "earth_eclipse_total";
  total.description =
      "2024-04-08 at greatest eclipse, on the ground at the centre of totality, looking north: "
      "the horizon's glow";
  total.body = "earth";
  total.exposure = 2e4;
  total.moon_pos_body = itrs * moon_pos_gcrs(utc);
  total.moon_radius = constants.moon_k_mean * constants.earth_radius;
  Body body = scene_body(total);
  Geodesy geodesy(body.shape);
  double sun_radius = load_atmosphere(body).sun_angular_radius;
  // The camera on the ground, its 60 degree field pitched up 31 degrees:
  // the horizon's ring of light along the bottom edge, sky above it and no
  // ground (the techniques are judged on their sky). The sun's direction
  // from the camera itself: from the Earth's centre it is up to 9 arcsec off, 1 %
  // of its radius.
  auto place = [&](Scene s, Geodetic g) {
    s.camera = geodesy.camera_at(g, 0.0, glm::radians(31.0), glm::radians(60.0));
    s.sun_dir_body = glm::normalize(sun_body - s.camera.pos_body);
    return s;
  };
  total = place(total, {eclipse->point.lat, eclipse->point.lon, 2.0});
  // Due north, the share rises from 0 at the umbra's edge: the latitude
  // where it is 10 %, by bisection.
  Scene partial = total;
  partial.name = "earth_eclipse_partial";
  partial.description =
      "2024-04-08 at greatest eclipse, on the ground north of totality where 10 % of the sun's "
      "flux is left, looking north";
  partial.exposure = 100.0;
  double lo = eclipse->point.lat, hi = lo + glm::radians(20.0);
  for (int i = 0; i < 60; ++i) {
    double mid = 0.5 * (lo + hi);
    Scene s = place(partial, {mid, eclipse->point.lon, 2.0});
    (sun_share(s, sun_radius, s.camera.pos_body) < 0.1 ? lo : hi) = mid;
  }
  partial = place(partial, {lo, eclipse->point.lon, 2.0});
  // From 400 km over the place 4 degrees north of the centre (445 km),
  // looking south 40 degrees down: the umbra near the middle of the view
  // (about 44 degrees below the horizontal), the penumbra about it, and the
  // limb, 20 degrees down, across the top of the field (10 to 70 down).
  Scene orbit = total;
  orbit.name = "earth_eclipse_400km";
  orbit.description =
      "2024-04-08 at greatest eclipse, from 400 km north of totality looking south: the umbra on "
      "the ground and the air, the penumbra about it, the limb";
  orbit.exposure = 8.0;
  const Geodetic over{eclipse->point.lat + glm::radians(4.0), eclipse->point.lon, 400e3};
  orbit.camera =
      geodesy.camera_at(over, glm::pi<double>(), glm::radians(-40.0), glm::radians(60.0));
  orbit.sun_dir_body = glm::normalize(sun_body - orbit.camera.pos_body);
  return {total, partial, orbit};
}

PathBudget lab_reference_paths(const Scene& scene) {
  return PathBudget(scene.name == "earth_noon_dense50" && scene.max_order != 1 ? 2048 : 8192);
}

PathBudget shipped_reference_paths(const std::string& scene_name) {
  struct Shipped {
    const char* scene;
    PathBudget paths;
  };
  static const Shipped kShipped[] = {
      {"earth_noon", PathBudget({40960, 147456, 335872})},
      {"earth_400km", PathBudget({98304, 180224, 655360})},
      {"earth_sunset", PathBudget({24576, 126976, 811008})},
      {"earth_twilight", PathBudget({430080, 339968, 704512})},
      {"mars_noon", PathBudget(196608)},
      {"mars_sunset", PathBudget({184320, 143360, 131072})},
  };
  find_scene(scene_name);  // an unknown name fails here
  for (const Shipped& s : kShipped) {
    if (scene_name == s.scene) return s.paths;
  }
  return PathBudget(4096);
}

Scene find_scene(const std::string& name) {
  std::string known;
  for (const Scene& s : canonical_scenes()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  // Only then the eclipse scenes, which ask the ephemeris.
  for (const Scene& s : eclipse_scenes()) {
    if (s.name == name) return s;
    known += ", " + s.name;
  }
  throw InputError(fmt::format("'{}' is not a canonical scene ({})", name, known));
}

Scene find_scene(const std::string& name, int width, int height) {
  Scene scene = find_scene(name);
  scene.width = width;
  scene.height = height;
  return scene;
}

Body scene_body(const Scene& scene) {
  Body body = load_body(find_body_file(scene.body));
  if (scene.bottom_radius && body.has_atmosphere()) {
    // The whole body scaled with its atmosphere's bottom, its shape kept.
    double bottom = body.atmosphere.at("bottom_radius_m").get<double>();
    body.shape.equatorial_radius *= *scene.bottom_radius / bottom;
  }
  // The ground truth's ground is the smooth bottom sphere, Lambertian with
  // the model's albedo. So that a technique is judged on its sky and not on
  // the terrain, the frame draws the same ground: the body's relief and
  // palette give way to a smooth surface of that one grey (terrain/'s
  // schema: no noise layers, every palette colour the same).
  if (body.has_atmosphere()) {
    // The albedo at the model's three wavelengths: one grey, or a spectrum's
    // (derived atmospheres, atmosphere_inputs.h).
    glm::dvec3 a = scene.target_albedo   ? glm::dvec3(*scene.target_albedo)
                   : scene.ground_albedo ? glm::dvec3(*scene.ground_albedo)
                                         : load_atmosphere(body).ground_albedo;
    nlohmann::json grey = {a.r, a.g, a.b};
    body.terrain = {
        {"max_level", 12},
        {"height", {{"type", "procedural"}, {"layers", nlohmann::json::array()}}},
        {"albedo",
         {{"low", grey}, {"high", grey}, {"steep", grey}, {"snow", grey}, {"ocean", grey}}},
    };
  }
  return body;
}

AtmosphereModel scene_atmosphere(const Scene& scene, const Body& body) {
  if (!body.has_atmosphere()) {
    throw InputError(
        fmt::format("{}: scene {}: the body has no atmosphere", body.file.string(), scene.name));
  }
  AtmosphereModel model = load_atmosphere(body);
  if (scene.scattering_scale != 1.0) model = with_scattering_scaled(model, scene.scattering_scale);
  if (scene.mie_g) model.mie_g = *scene.mie_g;
  if (scene.absorption_scale != 1.0) model = with_absorption_scaled(model, scene.absorption_scale);
  if (scene.scale_height_scale != 1.0) {
    model = with_scale_heights_scaled(model, scene.scale_height_scale);
  }
  if (scene.bottom_radius) {
    model = with_bottom_radius(model, *scene.bottom_radius, scene.absolute_thickness);
  }
  if (scene.ground_albedo) {
    model.ground_albedo = glm::dvec3(*scene.ground_albedo);
    if (model.spectrum) model.spectrum->ground_albedo.clear();  // the grey at every sample
  }
  return model;
}

std::string reference_stem(const Scene& scene) {
  std::string orders = scene.max_order > 0 ? fmt::format("-order{}", scene.max_order) : "";
  return fmt::format("{}{}-{}x{}", scene.name, orders, scene.width, scene.height);
}

int checked_max_order(int max_order, const std::string& where) {
  if (max_order < 0 || max_order > 1000) {
    throw InputError(fmt::format(
        "{}: {} is not an order count from 1 to 1000 (0 or none: every order)", where, max_order));
  }
  return max_order;
}

ReferenceSettings reference_settings(const Scene& scene, const PathBudget& paths) {
  ReferenceSettings settings;
  settings.paths = paths;
  settings.seed = scene.seed();
  settings.trace.max_order = scene.max_order;
  settings.trace.first_ground_albedo = scene.target_albedo.value_or(-1.0);
  return settings;
}

ReferenceView reference_view(const Scene& scene, const Body& body, const AtmosphereModel& model) {
  ReferenceView view;
  view.width = scene.width;
  view.height = scene.height;
  view.projection = scene.projection;
  glm::dvec3 scale = atmosphere_scale(body.shape, model.bottom_radius);
  view.camera_atmo = scale * scene.camera.pos_body;
  view.sun_dir_atmo = glm::normalize(scale * scene.sun_dir_body);
  // The Moon carried into atmosphere space as every point is, so that it
  // stands where it did relative to each; its radius by the same k (its
  // angular size kept).
  view.moon_centre_atmo = scale * scene.moon_pos_body;
  view.moon_radius = scale.x * scene.moon_radius;
  // The frame's own rays, pixel for pixel.
  view.ray_from_ndc =
      atmo_ray_from_ndc(scale, scene.camera, double(scene.width) / double(scene.height));
  // Equirectangular: the local east-north-up frame, carried into
  // atmosphere space and made orthonormal again.
  glm::dvec3 up = glm::normalize(view.camera_atmo);
  glm::dvec3 north_pole(0, 0, 1);
  glm::dvec3 east = glm::cross(north_pole, up);
  east = glm::length(east) > 1e-9 ? glm::normalize(east) : glm::dvec3(1, 0, 0);
  view.frame = glm::dmat3(east, glm::cross(up, east), up);
  return view;
}

}  // namespace planet
