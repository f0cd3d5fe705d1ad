#include "terrain/moonlight.h"

#include <algorithm>
#include <cmath>

namespace planet {

Moonlight moonlight(const Regolith& regolith, double radius, const glm::dvec3& sun,
                    const glm::dvec3& moon, const glm::dvec3& observer) {
  Moonlight m;
  const glm::dvec3 to_sun = sun - moon, to_observer = observer - moon;
  const double sun_distance = glm::length(to_sun), observer_distance = glm::length(to_observer);
  m.phase = std::acos(
      std::clamp(glm::dot(to_sun, to_observer) / (sun_distance * observer_distance), -1.0, 1.0));
  m.illuminated_fraction = 0.5 * (1.0 + std::cos(m.phase));
  m.disk_brightness = regolith_disk_brightness(regolith, m.phase);
  // A white Lambertian disk of radius R facing both the sun and the
  // observer, lit by E, has radiance E / pi over a solid angle pi R^2 / d^2:
  // E (R / d)^2 at the observer; the disk's brightness scales it. The sun's
  // irradiance at the Moon over that at the observer is the inverse
  // square of their distances from it.
  const double observer_sun_distance = glm::length(sun - observer);
  const double r = radius / observer_distance;
  const double sun_ratio =
      (observer_sun_distance / sun_distance) * (observer_sun_distance / sun_distance);
  m.over_sunlight = m.disk_brightness * r * r * sun_ratio;
  return m;
}

}  // namespace planet
