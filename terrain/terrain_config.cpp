#include "terrain/terrain_config.h"

#include "terrain/cage_height.h"
#include "terrain/grid_detail.h"
#include "terrain/grid_height.h"
#include "terrain/height_map.h"
#include "terrain/obj_cage.h"
#include "terrain/procedural_height.h"

#include "core/data_paths.h"
#include "core/error.h"
#include "core/json_reader.h"

#include <fmt/format.h>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>

namespace planet {

namespace {

glm::vec3 color(JsonObject& o, const std::string& key) {
  auto v = o.numbers(key, 3, 0.0, 1.0);
  return {float(v[0]), float(v[1]), float(v[2])};
}

NoiseLayer parse_layer(JsonObject& o) {
  NoiseLayer layer;
  std::string type = o.string("type");
  if (type == "fbm")
    layer.kind = NoiseLayer::Kind::kFbm;
  else if (type == "ridged")
    layer.kind = NoiseLayer::Kind::kRidged;
  else if (type == "craters")
    layer.kind = NoiseLayer::Kind::kCraters;
  else
    o.fail("type", fmt::format("'{}' is not a layer type (fbm, ridged, craters)", type));
  layer.amplitude = o.number("amplitude_m", 0.0, 1e5);
  layer.wavelength = o.number("wavelength_m", 1.0, 1e8);
  layer.octaves = o.integer("octaves", 1, 24);
  layer.gain = o.number_or("gain", 0.5, 0.0, 1.0);
  layer.lacunarity = o.number_or("lacunarity", 2.0, 1.1, 4.0);
  layer.density = o.number_or("density", 0.5, 0.0, 1.0);
  layer.seed = uint32_t(o.integer_or("seed", 1, 0, 1 << 30));
  o.finish();
  return layer;
}

// The imagery a body's file names, read once per process whatever the
// number of terrains built from it (and kept: about 33 MB for Earth's,
// where reading it again for each terrain took half a second); none,
// with a note, where its day image is not installed.
std::shared_ptr<const SurfaceMaps> load_maps(JsonObject& o, const Body& body) {
  SurfaceMapFiles files;
  files.day = o.string("day");
  if (o.has("night")) files.night = o.string("night");
  files.night_radiance = o.number_or("night_radiance", files.night_radiance, 0.0, 1.0);
  files.fade_start_m = o.number_or("fade_start_m", files.fade_start_m, 0.0, 1e8);
  files.fade_end_m = o.number_or("fade_end_m", files.fade_end_m, 0.0, 1e8);
  if (files.fade_end_m <= files.fade_start_m) o.fail("fade_end_m", "must be above fade_start_m");
  std::string note = o.string_or("missing_note", "");
  o.finish();
  for (auto* f : {&files.day, &files.night}) {
    if (!f->empty() && f->is_relative()) *f = project_root() / *f;
  }

  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const SurfaceMaps>> loaded;
  static std::map<std::string, bool> noted;
  std::lock_guard<std::mutex> lock(mutex);
  std::error_code ec;
  if (!std::filesystem::exists(files.day, ec)) {
    if (!noted[files.day.string()]) {
      std::fprintf(stderr, "planet: note: %s is not installed%s%s: %s's ground has its palette's colours\n",
                   files.day.string().c_str(), note.empty() ? "" : " ", note.c_str(),
                   body.name.c_str());
      noted[files.day.string()] = true;
    }
    return nullptr;
  }
  std::string key = fmt::format("{}|{}|{}|{}|{}|{}", files.day.string(), files.night.string(),
                                files.night_radiance, files.fade_start_m, files.fade_end_m,
                                body.shape.flattening);
  if (auto kept = loaded[key]) return kept;
  auto maps = std::make_shared<const SurfaceMaps>(files, body.shape.flattening);
  loaded[key] = maps;
  return maps;
}

// A grid's "datum": the surface its heights are reckoned from, which must
// be the body's base shape or stand in for it. A sphere must be the body's
// own (heights from it are radii); a geoid or an areoid (an equipotential
// surface) is laid on the body's ellipsoid, so their reference radii must
// agree to 0.1 % (the areoid's 3396.0 km against Mars's 3396.19 km ellipsoid).
void check_datum(JsonObject& o, const Body& body, const std::string& file) {
  std::string surface = o.string("surface");
  double radius = o.number("radius_m", 1.0, 1e9);
  o.finish();
  const double a = body.shape.equatorial_radius;
  if (surface == "sphere") {
    if (body.shape.flattening != 0.0 || std::abs(radius - a) > 1.0) {
      o.fail("radius_m", fmt::format("{}'s heights stand above a sphere of {} m, but {} is an "
                                     "ellipsoid of {} m with flattening {}",
                                     file, radius, body.name, a, body.shape.flattening));
    }
  } else if (surface == "geoid" || surface == "areoid") {
    if (std::abs(radius - a) > 1e-3 * a) {
      o.fail("radius_m", fmt::format("{}'s heights stand above the {} of {} m, which cannot stand "
                                     "for {}'s ellipsoid of {} m (another body's grid?)",
                                     file, surface, radius, body.name, a));
    }
  } else {
    o.fail("surface", fmt::format("'{}' is not a datum (sphere, geoid, areoid)", surface));
  }
}

// Grids read once per process whatever the number of terrains built from
// them (Earth's holds 19 MB of samples and takes about half a second to decode).
std::shared_ptr<const GridData> load_grid(const GridSpec& spec) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const GridData>> loaded;
  std::string key =
      fmt::format("{}|{}|{}|{}|{}|{}|{}|{}|{}", spec.file.string(), int(spec.layout),
                  int(spec.registration), spec.width, spec.height, spec.west_longitude_deg,
                  spec.scale, spec.offset, spec.geodetic_latitude);
  std::lock_guard<std::mutex> lock(mutex);
  if (auto kept = loaded[key]) return kept;
  auto data = std::make_shared<const GridData>(spec);
  loaded[key] = data;
  return data;
}

// A grid's "detail": the relief noise and craters below its cells
// (grid_detail.h); every field has a default.
GridDetailSpec parse_detail(JsonObject& o) {
  GridDetailSpec d;
  (void)o.string_or("about", "");  // what the values are for, for people
  d.relief_ratio = o.number_or("relief_ratio", d.relief_ratio, 0.0, 2.0);
  d.min_amplitude_m = o.number_or("min_amplitude_m", d.min_amplitude_m, 0.0, 1e4);
  d.max_amplitude_m = o.number_or("max_amplitude_m", d.max_amplitude_m, 0.0, 1e4);
  if (d.max_amplitude_m < d.min_amplitude_m)
    o.fail("max_amplitude_m", "must not be below min_amplitude_m");
  d.rough_relief_m = o.number_or("rough_relief_m", d.rough_relief_m, 1.0, 1e5);
  d.gain_smooth = o.number_or("gain_smooth", d.gain_smooth, 0.0, 0.9);
  d.gain_rough = o.number_or("gain_rough", d.gain_rough, 0.0, 0.9);
  d.sea_floor = o.number_or("sea_floor", d.sea_floor, 0.0, 1.0);
  d.octaves = o.integer_or("octaves", d.octaves, 0, 20);
  d.seed = uint32_t(o.integer_or("seed", int(d.seed), 0, 1 << 30));
  if (o.has("craters")) {
    JsonObject c = o.object("craters");
    d.crater_octaves = c.integer("octaves", 0, 16);
    d.crater_depth_ratio = c.number_or("depth_ratio", d.crater_depth_ratio, 0.0, 2.0);
    d.crater_density = c.number_or("density", d.crater_density, 0.0, 1.0);
    d.crater_sfd_exponent = c.number_or("sfd_exponent", d.crater_sfd_exponent, 1.0, 4.0);
    d.crater_seed = uint32_t(c.integer_or("seed", int(d.crater_seed), 0, 1 << 30));
    c.finish();
  }
  o.finish();
  return d;
}

std::shared_ptr<const HeightSource> parse_grid(JsonObject& o, const Body& body,
                                               std::optional<double>& sea_level,
                                               double mean_radius) {
  GridSpec spec;
  (void)o.string_or("source", "");  // where the grid comes from, for people
  spec.file = o.string("file");
  if (spec.file.is_relative()) spec.file = project_root() / spec.file;
  std::string layout = o.string("layout");
  if (layout == "int16_le")
    spec.layout = GridSpec::Layout::kInt16Le;
  else if (layout == "int16_be")
    spec.layout = GridSpec::Layout::kInt16Be;
  else if (layout == "png_u16")
    spec.layout = GridSpec::Layout::kPngU16;
  else
    o.fail("layout",
           fmt::format("'{}' is not a grid layout (int16_le, int16_be, png_u16)", layout));
  std::string registration = o.string("registration");
  if (registration == "pixel")
    spec.registration = GridSpec::Registration::kPixel;
  else if (registration == "node")
    spec.registration = GridSpec::Registration::kNode;
  else
    o.fail("registration", fmt::format("'{}' is not a registration (pixel, node)", registration));
  spec.width = o.integer("width", 4, 1 << 20);
  spec.height = o.integer("height", 2, 1 << 20);
  spec.west_longitude_deg = o.number_or("west_longitude_deg", 0.0, -360.0, 360.0);
  spec.scale = o.number("scale_m", 1e-6, 1e3);
  spec.offset = o.number_or("offset_m", 0.0, -1e5, 1e5);
  std::string latitude = o.string("latitude");
  if (latitude == "geodetic")
    spec.geodetic_latitude = true;
  else if (latitude != "planetocentric")
    o.fail("latitude", fmt::format("'{}' is not a latitude (geodetic, planetocentric)", latitude));
  JsonObject datum = o.object("datum");
  check_datum(datum, body, spec.file.string());
  if (o.has("sea_level_m")) sea_level = o.number("sea_level_m", -1e5, 1e5);
  std::optional<GridDetailSpec> detail;
  if (o.has("detail")) {
    JsonObject d = o.object("detail");
    detail = parse_detail(d);
  }
  o.finish();
  double b = body.shape.polar_radius(), a = body.shape.equatorial_radius;
  if (detail) {
    return std::make_shared<GridDetail>(load_grid(spec), mean_radius, (a * a) / (b * b),
                                        sea_level, *detail);
  }
  return std::make_shared<GridHeight>(load_grid(spec), mean_radius, (a * a) / (b * b), sea_level);
}

std::shared_ptr<const HeightSource> parse_heights(JsonObject& o, const Body& body,
                                                  std::optional<double>& sea_level,
                                                  const std::shared_ptr<const SurfaceMaps>& maps) {
  std::string type = o.string("type");
  double mean_radius = (2.0 * body.shape.equatorial_radius + body.shape.polar_radius()) / 3.0;
  if (type == "procedural") {
    std::vector<NoiseLayer> layers;
    for (JsonObject& l : o.objects("layers")) layers.push_back(parse_layer(l));
    double offset = o.number_or("offset_m", 0.0, -1e5, 1e5);
    if (o.has("sea_level_m")) sea_level = o.number("sea_level_m", -1e5, 1e5);
    o.finish();
    auto heights =
        std::make_shared<ProceduralHeight>(mean_radius, std::move(layers), offset, sea_level);
    if (maps && sea_level) heights->set_land_mask(maps);
    return heights;
  }
  if (type == "height_map") {
    std::filesystem::path file = o.string("file");
    if (file.is_relative()) file = project_root() / file;
    double scale = o.number("scale_m", -1e5, 1e5);
    double offset = o.number_or("offset_m", 0.0, -1e5, 1e5);
    o.finish();
    auto map = std::make_shared<HeightMap>(file, scale, offset);
    map->set_body_radius(mean_radius);
    return map;
  }
  if (type == "grid") return parse_grid(o, body, sea_level, mean_radius);
  if (type == "cage") {
    std::filesystem::path file = o.string("file");
    if (file.is_relative()) file = project_root() / file;
    std::vector<NoiseLayer> layers;
    if (o.has("layers")) {
      for (JsonObject& l : o.objects("layers")) layers.push_back(parse_layer(l));
    }
    // A measured shape model in the body's own frame gives its file's unit
    // (1000 for km) and is taken as it is; an artistic cage leaves it out
    // and is fitted to the body's radius.
    std::optional<double> units_m;
    if (o.has("units_m")) units_m = o.number("units_m", 1e-3, 1e6);
    o.finish();
    return std::make_shared<CageHeight>(read_obj_cage(file), file.string(), mean_radius,
                                        std::move(layers), units_m);
  }
  o.fail("type",
         fmt::format("'{}' is not a height source (procedural, grid, height_map, cage)", type));
}

}  // namespace

TerrainConfig parse_terrain(const Body& body) {
  TerrainConfig config;
  if (body.terrain.is_null()) {
    config.heights = std::make_shared<ProceduralHeight>(
        body.shape.equatorial_radius, std::vector<NoiseLayer>{}, 0.0, std::nullopt);
    config.max_level = 12;
    return config;
  }
  JsonObject root(body.terrain, body.file.string(), "terrain");
  config.max_level = root.integer_or("max_level", 20, 0, 24);
  if (root.has("maps")) {
    JsonObject maps = root.object("maps");
    config.maps = load_maps(maps, body);
  }
  JsonObject heights = root.object("height");
  config.heights = parse_heights(heights, body, config.sea_level, config.maps);
  if (root.has("sea")) {
    JsonObject sea = root.object("sea");
    // Cox and Munk's fit of the slopes to the wind rests on winds of up to
    // 14 m/s; past 15 the sea breaks into foam that it does not model.
    config.sea_wind = sea.number("wind_m_s", 0.0, 15.0);
    (void)sea.string_or("about", "");  // for people
    sea.finish();
  }
  if (root.has("albedo")) {
    JsonObject a = root.object("albedo");
    SurfacePalette& p = config.palette;
    p.low = color(a, "low");
    p.high = color(a, "high");
    p.steep = color(a, "steep");
    if (a.has("snow")) p.snow = color(a, "snow");
    if (a.has("ocean")) p.ocean = color(a, "ocean");
    p.low_height = a.number_or("low_height_m", p.low_height, -1e5, 1e5);
    p.high_height = a.number_or("high_height_m", p.high_height, -1e5, 1e5);
    if (p.high_height <= p.low_height) a.fail("high_height_m", "must be above low_height_m");
    p.snow_line_equator = a.number_or("snow_line_equator_m", p.snow_line_equator, -1e5, 1e5);
    p.snow_line_pole = a.number_or("snow_line_pole_m", p.snow_line_pole, -1e5, 1e5);
    p.steep_slope = a.number_or("steep_slope", p.steep_slope, 0.01, 1.0);
    p.materials = a.boolean_or("materials", false);
    if (a.has("variation")) {
      for (JsonObject v : a.objects("variation")) {
        AlbedoVariation layer;
        layer.wavelength = v.number("wavelength_m", 0.1, 1e8);
        layer.octaves = v.integer("octaves", 1, 24);
        layer.gain = v.number_or("gain", layer.gain, 0.0, 1.0);
        layer.amplitude = v.number("amplitude", 0.0, 0.95);
        layer.seed = uint32_t(v.integer_or("seed", 0, 0, 1 << 30));
        v.finish();
        p.variation.push_back(layer);
      }
    }
    if (a.has("craters")) {
      JsonObject c = a.object("craters");
      p.craters.floor = c.number_or("floor", 0.0, -0.9, 2.0);
      p.craters.rim = c.number_or("rim", 0.0, -0.9, 2.0);
      p.craters.ejecta = c.number_or("ejecta", 0.0, -0.9, 2.0);
      c.finish();
    }
    a.finish();
  }
  if (root.has("regolith")) {
    JsonObject o = root.object("regolith");
    Regolith r;
    r.w = o.number("w", 0.0, 0.999);
    r.xi = o.number("xi", -0.95, 0.95);
    r.b0 = o.number("b0", 0.0, 5.0);
    r.h = o.number("h", 1e-3, 2.0);
    r.theta_bar = glm::radians(o.number("theta_bar_deg", 0.0, 60.0));
    r.source = o.string("source");
    o.finish();
    config.regolith = r;
  }
  root.finish();
  return config;
}

}  // namespace planet
