// The lab's references ship: every canonical scene with an atmosphere, and
// its first order, at the size and paths planet lab run measures with
// (lab/scene.h), each with its noise; so the default sweep never starts a
// path trace.
#include "core/data_paths.h"
#include "lab/reference_cache.h"
#include "lab/scene.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(LabReferencesTest, EverySceneAndItsFirstOrderShipAtTheLabsSize) {
  int scenes = 0;
  for (Scene scene : canonical_scenes()) {
    Body body = scene_body(scene);
    if (!body.has_atmosphere()) continue;
    ++scenes;
    scene.width = kLabWidth;
    scene.height = kLabHeight;
    for (int max_order : {0, 1}) {
      scene.max_order = max_order;
      std::filesystem::path file =
          shipped_reference_dir() / reference_cache_file(scene, scene_atmosphere(scene, body),
                                                         lab_reference_paths(scene),
                                                         ReferenceMode::kRgb)
                                        .filename();
      EXPECT_TRUE(std::filesystem::exists(file)) << file;
      EXPECT_TRUE(std::filesystem::exists(reference_noise_file(file))) << file;
    }
  }
  EXPECT_EQ(scenes, 12);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
