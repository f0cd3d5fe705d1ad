// What every shipped flight shows, checked on a frame every ten: something
// to see (no frame near black), and its keyframes above the ground.
#include "render/capture.h"

#include "core/data_paths.h"
#include "core/image_io.h"
#include "gl/context.h"
#include "terrain/ground.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

class ShippedFlightGLTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedFlightGLTest, NoFrameIsBlackAndNoKeyframeIsUnderground) {
  const GroundHeight ground = terrain_ground();
  FlightScript script = load_flight_script(data_dir() / "flights" / (GetParam() + ".json"), ground);
  EXPECT_NO_THROW(check_keyframes_above_ground(script, ground));
  // A quarter of the size: what is seen, not its detail.
  script.width /= 4;
  script.height /= 4;
  auto context = GlContext::create_headless();
  auto dir = std::filesystem::temp_directory_path() /
             ("planet-shipped-" + GetParam() + "-" + std::to_string(getpid()));
  for (int frame = 0; frame < script.frame_count(); frame += 10) {
    CaptureOptions options;
    options.out_dir = dir;
    options.first_frame = frame;
    options.end_frame = frame + 1;
    options.progress = false;
    run_capture(script, options);
    ImageRGB png = read_image_rgb(dir / fmt::format("frame_{:05d}.png", frame));
    // A pixel counts as seen above a tenth of the 8-bit range (about 1 %
    // of the radiance that maps to white); 1 % of the frame must be.
    int seen = 0, pixels = png.width * png.height;
    for (int i = 0; i < pixels; ++i) {
      const float* p = &png.pixels[size_t(i) * 3];
      if (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] > 0.1f) ++seen;
    }
    EXPECT_GE(seen, pixels / 100) << GetParam() << " frame " << frame << " is near black (" << seen
                                  << " of " << pixels << " pixels seen)";
  }
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Flights, ShippedFlightGLTest,
                         ::testing::Values("alps_shafts", "alps_sunset", "ascent",
                                           "asteroid_landing", "clouds_climb", "clouds_orbit",
                                           "alps_nightfall", "coast_sunset", "eclipse_texas",
                                           "eros_landing", "earth_night_lights",
                                           "earth_orbit_terminator", "everest_dawn",
                                           "governed_ascent", "mars_crater_sunset", "mars_sunset",
                                           "moon_descent", "olympus_mons", "sea_glint_orbit",
                                           "terrain_asteroid", "terrain_earth", "terrain_mars",
                                           "tycho_landing", "valles_marineris"),
                         [](const auto& instance) { return instance.param; });

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
