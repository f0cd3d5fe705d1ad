// Elevation grids (a body's "terrain": {"height": {"type": "grid", ...}}):
// raw 16-bit samples of either byte order, or a 16-bit PNG read through
// OpenImageIO. The first byte picks the layout and registration, the next
// two the declared width and height; the rest is the file.
#include "fuzz_input.h"
#include "terrain/grid_height.h"

#include <glm/glm.hpp>

PLANET_FUZZ_TARGET(grid_height) {
  if (size < 3) return 0;
  using planet::GridSpec;
  static const GridSpec::Layout kLayouts[] = {
      GridSpec::Layout::kInt16Le, GridSpec::Layout::kInt16Be, GridSpec::Layout::kPngU16};
  GridSpec spec;
  spec.layout = kLayouts[data[0] % 3];
  spec.registration =
      (data[0] / 3) % 2 ? GridSpec::Registration::kNode : GridSpec::Registration::kPixel;
  spec.geodetic_latitude = (data[0] / 6) % 2;
  spec.width = 2 + 2 * (data[1] % 40);  // 2 (refused) to 80, even
  spec.height = 1 + data[2] % 40;       // 1 (refused) to 40
  spec.scale = 0.5;
  spec.file =
      planet::fuzz::write_input(planet::fuzz::as_text(data + 3, size - 3),
                                spec.layout == GridSpec::Layout::kPngU16 ? "grid.png" : "grid.img");
  planet::fuzz::expect_only_input_errors([&] {
    planet::GridHeight grid(std::make_shared<planet::GridData>(spec), 1e6, 1.01, std::nullopt);
    for (glm::dvec3 d : {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0),
                         glm::normalize(glm::dvec3(0.3, -0.5, 0.8))}) {
      (void)grid.height(d);
      (void)grid.range_near(d, 1e5);
      (void)grid.range_near(d, 5e6);
    }
    (void)grid.interpolation_error(100.0);
  });
  return 0;
}
