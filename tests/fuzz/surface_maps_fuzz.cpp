// A body's day and night imagery (its "terrain": {"maps": {...}}): JPEG
// through stb_image, the other formats through OpenImageIO. The first
// byte picks the file's extension.
#include "fuzz_input.h"
#include "terrain/surface_maps.h"

#include <glm/glm.hpp>

PLANET_FUZZ_TARGET(surface_maps) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".jpg", ".png", ".tif", ".pgm"};
  const char* extension = kExtensions[data[0] % 4];
  std::filesystem::path file = planet::fuzz::write_input(planet::fuzz::as_text(data + 1, size - 1),
                                                         std::string("day") + extension);
  planet::fuzz::expect_only_input_errors([&] {
    planet::SurfaceMaps maps({file, file}, 0.0033528);
    glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    (void)maps.land(d);
    (void)maps.distance_to_coast(d);
    (void)maps.land(glm::dvec3(0, 0, 1));
    (void)maps.distance_to_coast(glm::dvec3(0, 0, -1));
  });
  return 0;
}
