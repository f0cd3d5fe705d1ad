// Body files (data/planets/*.json): the body, its atmosphere (coefficients
// or a day's inputs) and its terrain's settings.
#include "atmosphere/model.h"
#include "fuzz_input.h"
#include "sim/body.h"
#include "terrain/terrain_config.h"

PLANET_FUZZ_TARGET(body) {
  std::filesystem::path file = planet::fuzz::write_input(planet::fuzz::as_text(data, size),
                                                         "body.json");
  planet::fuzz::expect_only_input_errors([&] {
    planet::Body body = planet::load_body(file);
    if (body.has_atmosphere()) planet::load_atmosphere(body);
    // A terrain that names a height map or a cage reads that file, which
    // could be any path: those formats have targets of their own.
    if (body.terrain.dump().find("\"file\"") == std::string::npos) planet::parse_terrain(body);
  });
  return 0;
}
