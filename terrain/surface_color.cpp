#include "terrain/surface_color.h"

#include <algorithm>
#include <cmath>

namespace planet {

namespace {
double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
}  // namespace

glm::vec3 surface_albedo(const SurfacePalette& p, double height, double slope, double latitude,
                         bool at_sea) {
  if (at_sea && p.ocean) return *p.ocean;
  glm::vec3 c = glm::mix(p.low, p.high, float(smoothstep(p.low_height, p.high_height, height)));
  c = glm::mix(c, p.steep, float(smoothstep(0.5 * p.steep_slope, p.steep_slope, slope)));
  if (p.snow) {
    // The snow line falls with |latitude| as cos^2, and snow slides off
    // steep slopes, where rock shows through.
    double cl = std::cos(latitude);
    double line = p.snow_line_pole + (p.snow_line_equator - p.snow_line_pole) * cl * cl;
    double snow = smoothstep(line - 300.0, line + 300.0, height) *
                  (1.0 - smoothstep(0.3 * p.steep_slope, 0.8 * p.steep_slope, slope));
    c = glm::mix(c, *p.snow, float(snow));
  }
  return c;
}

}  // namespace planet
