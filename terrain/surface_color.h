#pragma once
// Surface albedo from what the ground is: height, slope and latitude pick
// between a body's palette (lowland, highland, rock on steep slopes, snow
// or ice above a snow line that falls toward the poles, and ocean).
#include "terrain/height_source.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace planet {

// Brightness that varies over the ground whatever its height: fBm of
// gradient noise from `wavelength` down through `octaves` halvings
// (amplitudes falling by `gain`), which scales the albedo by 1 +
// amplitude * noise. Mars's bright and dark provinces at 1000 km, the
// streaks and patches of dust at a few km, regolith to the metre.
struct AlbedoVariation {
  double wavelength = 1e6;  // metres
  int octaves = 4;
  double gain = 0.5;
  double amplitude = 0.2;   // of the fBm, which stays within about [-1, 1]
  uint32_t seed = 0;
};

// What craters do to the albedo of the land they mark: it is scaled by
// (1 + floor F)(1 + rim R)(1 + ejecta E) for the marks' shares F, R, E.
// Mars's dark dunes pooled on crater floors and bright rims; the Moon's
// bright young ejecta and rays.
struct CraterAlbedo {
  double floor = 0, rim = 0, ejecta = 0;  // each in [-0.9, 2]
};

struct SurfacePalette {
  glm::vec3 low{0.25f, 0.22f, 0.18f};
  glm::vec3 high{0.35f, 0.32f, 0.28f};
  glm::vec3 steep{0.3f, 0.3f, 0.3f};
  std::optional<glm::vec3> snow;   // none: no snow or ice
  std::optional<glm::vec3> ocean;  // none: no ocean
  double low_height = 0;           // metres: fully `low` at and below
  double high_height = 3000;       // metres: fully `high` at and above
  double snow_line_equator = 5000; // metres above which snow lies at the equator
  double snow_line_pole = 0;       // ... and at the poles
  double steep_slope = 0.6;        // 1 - cos(angle to the vertical) at which rock shows fully
  std::vector<AlbedoVariation> variation;  // applied in turn to land (not to sea or snow)
  CraterAlbedo craters;                    // applied to land with the variation
  // Earth's materials by rule (ground_material.h) on land in the place of
  // the palette's land colours, the snow line and the steep slopes.
  bool materials = false;
};

// The land's albedo (the sea's, where the palette has one, terrain.frag
// draws from the ground's height over it). `slope`: 1 - dot(normal, up).
// `latitude`: radians. `position`: the point in the body frame, metres,
// where the variation's noise is sampled; `spacing`: the distance to the
// next sample (a tile's vertex), below twice which no octave of the
// variation is summed (sampled more coarsely, the finer octaves alias into
// specks on distant ground). `marks`: the craters' at the point, on
// samples of that spacing.
glm::vec3 surface_albedo(const SurfacePalette& palette, double height, double slope,
                         double latitude, const glm::dvec3& position, double spacing,
                         const CraterMarks& marks = {});

// The factor the craters' marks scale the albedo by, within [0.05, 4].
double crater_albedo(const CraterAlbedo& craters, const CraterMarks& marks);

// How much of the ground's colour at a land point a map of the body's
// colour can give, in [0, 1]: all of it but where steep rock or snow show
// (which the palette resolves and a map's coarse pixels do not).
double map_cover(const SurfacePalette& palette, double height, double slope, double latitude);

// The factor `variation` scales the albedo by at `position`, within
// [0.05, 2]: octaves fade out from a wavelength of 4 `spacing` to 2.
double albedo_variation(const std::vector<AlbedoVariation>& variation,
                        const glm::dvec3& position, double spacing);

}  // namespace planet
