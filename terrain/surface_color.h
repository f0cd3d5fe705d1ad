#pragma once
// Surface albedo from what the ground is: height, slope and latitude pick
// between a body's palette (lowland, highland, rock on steep slopes, snow
// or ice above a snow line that falls toward the poles, and ocean).
#include <glm/glm.hpp>

#include <optional>

namespace planet {

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
};

// `slope`: 1 - dot(normal, up). `latitude`: radians. `at_sea`: the point
// is open sea (at sea level).
glm::vec3 surface_albedo(const SurfacePalette& palette, double height, double slope,
                         double latitude, bool at_sea);

}  // namespace planet
