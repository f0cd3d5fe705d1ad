// Height maps (a body's "terrain": {"height_map": {"file": ...}}), read
// through OpenImageIO. The first byte picks the file's extension, which is
// how OpenImageIO picks its reader first.
#include "fuzz_input.h"
#include "terrain/height_map.h"

#include <glm/glm.hpp>

PLANET_FUZZ_TARGET(height_map) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".png", ".exr", ".tif", ".pgm", ".hdr", ".jpg"};
  const char* extension = kExtensions[data[0] % 6];
  std::filesystem::path file = planet::fuzz::write_input(
      planet::fuzz::as_text(data + 1, size - 1), std::string("heights") + extension);
  planet::fuzz::expect_only_input_errors([&] {
    planet::HeightMap map(file, 1.0, 0.0);
    (void)map.height(glm::normalize(glm::dvec3(0.3, -0.5, 0.8)));
    (void)map.range_near(glm::dvec3(0, 0, 1), 1e5);
    (void)map.interpolation_error(100.0);
  });
  return 0;
}
