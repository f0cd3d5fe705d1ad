#include "clouds/cloud_model.h"

#include "core/error.h"

#include <fmt/format.h>

namespace planet {

CloudModel parse_clouds(JsonObject c, double atmosphere_height) {
  CloudModel m;
  m.bottom_altitude = c.number("bottom_altitude_m", 0.0, atmosphere_height);
  m.top_altitude = c.number("top_altitude_m", 0.0, atmosphere_height);
  if (m.top_altitude <= m.bottom_altitude) {
    c.fail("top_altitude_m", fmt::format("{} m must be above bottom_altitude_m ({} m)",
                                         m.top_altitude, m.bottom_altitude));
  }
  JsonObject w = c.object("weather");
  std::string type = w.string("type");
  if (type != "procedural") {
    w.fail("type", fmt::format("'{}' is not a known weather (procedural)", type));
  }
  m.coverage = w.number("coverage", 0.0, 1.0);
  m.cumulus_share = w.number("cumulus_share", 0.0, 1.0);
  // A cell of at least a kilometre; below that the weather is the shape.
  m.weather_scale = w.number("scale_m", 1e3, 1e8);
  // Below 2^24 the seed is exact in the shaders' float.
  m.seed = w.integer("seed", 0, (1 << 24) - 1);
  w.string_or("about", "");
  w.finish();
  m.shape_scale = c.number("shape_scale_m", 10.0, 1e7);
  m.erosion_scale = c.number("erosion_scale_m", 1.0, 1e7);
  m.erosion = c.number("erosion", 0.0, 1.0);
  // Thicker than fog at 1/m would leave a march's steps meaningless.
  m.extinction = c.number("extinction_per_m", 0.0, 1.0);
  m.albedo = c.number("single_scattering_albedo", 0.0, 1.0);
  // The phase function's fit holds from 1.5 to 50 um (cloud_phase.glsl).
  m.droplet_diameter_um = c.number("droplet_diameter_um", 1.5, 50.0);
  c.string_or("source", "");
  c.finish();
  return m;
}

std::optional<CloudModel> load_clouds(const Body& body) {
  if (body.clouds.is_null()) return std::nullopt;
  JsonObject c(body.clouds, body.file.string(), "clouds");
  if (!body.has_atmosphere()) c.fail("clouds need the body's \"atmosphere\"");
  JsonObject a(body.atmosphere, body.file.string(), "atmosphere");
  double height = a.number("top_radius_m") - a.number("bottom_radius_m");
  return parse_clouds(c, height);
}

shared::CloudLayer to_shared(const CloudModel& m, double bottom_radius) {
  shared::CloudLayer l{};
  l.bottom_radius = bottom_radius + m.bottom_altitude;
  l.top_radius = bottom_radius + m.top_altitude;
  l.coverage = m.coverage;
  l.cumulus_share = m.cumulus_share;
  l.weather_scale = m.weather_scale;
  l.shape_scale = m.shape_scale;
  l.erosion_scale = m.erosion_scale;
  l.erosion = m.erosion;
  l.extinction = m.extinction;
  l.albedo = m.albedo;
  l.droplet_diameter_um = m.droplet_diameter_um;
  l.seed = m.seed;
  return l;
}

}  // namespace planet
