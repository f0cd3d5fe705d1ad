// The reference cache's images (.exr, and their .noise.exr), as the lab
// reads them back.
#include "core/image_io.h"
#include "fuzz_input.h"

PLANET_FUZZ_TARGET(reference_exr) {
  std::filesystem::path file =
      planet::fuzz::write_input(planet::fuzz::as_text(data, size), "reference.exr");
  planet::fuzz::expect_only_input_errors([&] { (void)planet::read_image_rgb(file); });
  return 0;
}
