// The Moon's shadow in the frame (FrameRenderer::set_moon): the raymarch
// technique multiplies the sun at each sample of its march by the visible
// share there (occluded_sun.glsl), as the ground truth does.
#include "gl/context.h"
#include "lab/gpu/scene_render.h"
#include "lab/scene.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

glm::dvec3 mean_rgb(const ImageRGB& image) {
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < image.pixels.size(); i += 3) {
    sum += glm::dvec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
  }
  return sum / double(image.pixels.size() / 3);
}

TEST(EclipseGLTest, TheRaymarchedSkyDimsByTheShareOfTheSunAlongItsRays) {
  auto context = GlContext::create_headless();
  for (const char* name : {"earth_eclipse_partial", "earth_eclipse_total"}) {
    Scene scene = find_scene(name);
    scene.width = 32;
    scene.height = 16;
    Scene clear = scene;
    clear.moon_radius = 0;
    glm::dvec3 eclipsed = mean_rgb(render_scene_with(scene, "raymarch"));
    glm::dvec3 lit = mean_rgb(render_scene_with(clear, "raymarch"));
    glm::dvec3 ratio = eclipsed / lit;
    std::printf("%s: raymarch sky with the Moon / without: %.4f %.4f %.4f\n", name, ratio.r,
                ratio.g, ratio.b);
    for (int c = 0; c < 3; ++c) {
      if (scene.name == "earth_eclipse_partial") {
        // A tenth of the sun at the camera; more along rays that reach out
        // of the shadow's deepest part, less toward it.
        EXPECT_GT(ratio[c], 0.05) << name;
        EXPECT_LT(ratio[c], 0.3) << name;
      } else {
        // In the umbra the first order is the light of the air outside it.
        EXPECT_LT(ratio[c], 0.01) << name;
      }
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
