// Wavefront OBJ cages (a body's "terrain": {"cage": {"file": ...}}): read,
// checked, and refined once by OpenSubdiv as the terrain does.
#include "fuzz_input.h"
#include "terrain/cage_height.h"
#include "terrain/obj_cage.h"

PLANET_FUZZ_TARGET(obj_cage) {
  std::filesystem::path file = planet::fuzz::write_input(planet::fuzz::as_text(data, size),
                                                         "cage.obj");
  planet::fuzz::expect_only_input_errors([&] {
    planet::ObjCage cage = planet::read_obj_cage(file);
    // Refining is linear in the faces: small cages only, to keep the rate.
    if (cage.face_sizes.size() <= 512) planet::cage_limit_points(cage, 1, file.string());
  });
  return 0;
}
