#include "terrain/surface_color.h"

#include "terrain/noise.h"

#include <algorithm>
#include <cmath>

namespace planet {

namespace {
double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
}  // namespace

double albedo_variation(const std::vector<AlbedoVariation>& variation,
                        const glm::dvec3& position, double spacing) {
  double factor = 1.0;
  for (const AlbedoVariation& v : variation) {
    double sum = 0.0, amplitude = 1.0, norm = 0.0, wavelength = v.wavelength;
    for (int octave = 0; octave < v.octaves; ++octave) {
      // The whole series' norm, so that a coarse sample sums less detail,
      // not louder coarse octaves.
      norm += amplitude;
      double kept = smoothstep(2.0 * spacing, 4.0 * spacing, wavelength);
      if (kept > 0.0) {
        sum += kept * amplitude *
               gradient_noise(position / wavelength, v.seed + uint32_t(octave));
      }
      amplitude *= v.gain;
      wavelength *= 0.5;
    }
    // Gradient noise rarely leaves [-0.7, 0.7]: stretched toward [-1, 1].
    factor *= 1.0 + v.amplitude * std::clamp(1.4 * sum / norm, -1.0, 1.0);
  }
  return std::clamp(factor, 0.05, 2.0);
}

namespace {
double rock_share(const SurfacePalette& p, double slope) {
  return smoothstep(0.5 * p.steep_slope, p.steep_slope, slope);
}
double snow_share(const SurfacePalette& p, double height, double slope, double latitude) {
  if (!p.snow) return 0.0;
  // The snow line falls with |latitude| as cos^2, and snow slides off
  // steep slopes, where rock shows through.
  double cl = std::cos(latitude);
  double line = p.snow_line_pole + (p.snow_line_equator - p.snow_line_pole) * cl * cl;
  return smoothstep(line - 300.0, line + 300.0, height) *
         (1.0 - smoothstep(0.3 * p.steep_slope, 0.8 * p.steep_slope, slope));
}
}  // namespace

double map_cover(const SurfacePalette& p, double height, double slope, double latitude) {
  return (1.0 - rock_share(p, slope)) * (1.0 - snow_share(p, height, slope, latitude));
}

double crater_albedo(const CraterAlbedo& c, const CraterMarks& m) {
  return std::clamp((1.0 + c.floor * m.floor) * (1.0 + c.rim * m.rim) * (1.0 + c.ejecta * m.ejecta),
                    0.05, 4.0);
}

glm::vec3 surface_albedo(const SurfacePalette& p, double height, double slope, double latitude,
                         const glm::dvec3& position, double spacing, const CraterMarks& marks) {
  glm::vec3 c = glm::mix(p.low, p.high, float(smoothstep(p.low_height, p.high_height, height)));
  c = glm::mix(c, p.steep, float(rock_share(p, slope)));
  if (!p.variation.empty()) {
    c = glm::min(c * float(albedo_variation(p.variation, position, spacing)), glm::vec3(1.0f));
  }
  if (marks.floor > 0.0 || marks.rim > 0.0 || marks.ejecta > 0.0) {
    c = glm::min(c * float(crater_albedo(p.craters, marks)), glm::vec3(1.0f));
  }
  if (p.snow) c = glm::mix(c, *p.snow, float(snow_share(p, height, slope, latitude)));
  return c;
}

}  // namespace planet
