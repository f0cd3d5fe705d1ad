#pragma once
// How much light a regolith body (the Moon) sends to an observer: its
// phase angle and its irradiance there over the sun's, from Hapke's law
// integrated over its lit disk (terrain/regolith.h). The physics of the
// Moon as a light; docs/eclipses.md#moonlight.
#include "terrain/regolith.h"

#include <glm/glm.hpp>

namespace planet {

struct Moonlight {
  double phase = 0;  // radians: the angle at the Moon between the Sun and the observer
  double illuminated_fraction = 0;  // of the disk's area, (1 + cos phase) / 2
  double disk_brightness = 0;  // regolith_disk_brightness at the phase: the geometric albedo at 0
  // The Moon's irradiance at the observer, on a plane facing it, over the
  // sun's there (on a plane facing the sun), outside any air: in the band
  // the law's parameters were fitted in (V for the Moon). The Moon is
  // taken as grey: its spectrum is the sun's.
  double over_sunlight = 0;
};

// The light of a body of radius `radius` whose ground reflects by
// `regolith`, at `observer`; the three positions in one frame, metres.
// The body's disk is taken as seen from afar (its distance over its radius
// is 221 for the Moon from Earth, where the disk's brightness changes by
// under 1 % from the exact sphere's).
Moonlight moonlight(const Regolith& regolith, double radius, const glm::dvec3& sun,
                    const glm::dvec3& moon, const glm::dvec3& observer);

}  // namespace planet
