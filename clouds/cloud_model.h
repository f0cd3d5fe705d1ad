#pragma once
// A body's cloud layer, from the "clouds" object of its file: a shell of
// altitudes above the atmosphere's bottom, procedural weather, the noises'
// scales and the droplets' optics. No "clouds" object, no clouds. Every
// cloud renderer and the tests read the shared form (to_shared).
#include "clouds/math/cloud_math.h"
#include "core/json_reader.h"
#include "sim/body.h"

#include <optional>

namespace planet {

struct CloudModel {
  // Altitudes above the atmosphere's bottom radius (the sky's ground), m.
  double bottom_altitude = 0;
  double top_altitude = 0;
  // The procedural weather (the only kind so far): mean cover, share of
  // cumulus, cell size (m) and seed.
  double coverage = 0;
  double cumulus_share = 0;
  double weather_scale = 0;
  int seed = 0;
  double shape_scale = 0;    // m
  double erosion_scale = 0;  // m
  double erosion = 0;        // 0..1
  double extinction = 0;     // 1/m at density 1
  double albedo = 0;         // single scattering
  double droplet_diameter_um = 0;
};

// Parses a "clouds" object; `atmosphere_height` (top minus bottom radius,
// m) bounds the layer's top. Errors name the file and the field.
CloudModel parse_clouds(JsonObject clouds, double atmosphere_height);

// The body's clouds, or none where its file has no "clouds" object. A body
// with clouds but no atmosphere is an error.
std::optional<CloudModel> load_clouds(const Body& body);

// The shared math's form, radii from the centre of a planet whose sky's
// ground lies at `bottom_radius`.
shared::CloudLayer to_shared(const CloudModel& clouds, double bottom_radius);

}  // namespace planet
