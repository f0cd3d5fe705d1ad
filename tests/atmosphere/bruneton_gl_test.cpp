// The bruneton technique: one order is single scattering (against a fine
// brute-force march), a corrupt table file on disk is reported and rebuilt,
// and the precompute reports its time per order; the cache's limit.
#include "atmosphere/gpu/bruneton/bruneton_cache.h"
#include "atmosphere/gpu/bruneton/bruneton_technique.h"
#include "atmosphere/gpu/registry.h"
#include "gl/context.h"
#include "gl/texture.h"
#include "lab/accuracy.h"
#include "lab/gpu/scene_render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// Small tables: a precompute of a second or two on llvmpipe.
BrunetonTechnique::Settings small_settings() {
  BrunetonTechnique::Settings s;
  s.r = 16;
  s.mu = 64;
  s.mu_s = 16;
  s.nu = 4;
  s.orders = 2;
  return s;
}

class BrunetonGLTest : public ::testing::Test {
 protected:
  void SetUp() override { context_ = GlContext::create_headless(); }
  std::unique_ptr<GlContext> context_;
};

// With one order and no tail the tables hold single scattering alone, the
// raymarch technique's physics: at its fine quality (128 steps along the
// view, 64 to the sun) the two agree over the open sky (the ground is lit by
// each technique's own sky irradiance, which differs). At Bruneton's 2017
// sizes, measured R / G / B: earth_noon 0.04 / 0.78 / 0.52 %, mars_noon
// 0.07 / 0.06 / 0.07 %, earth_sunset 0.99 / 6.61 / 4.60 % (32 sun zenith
// cosines: the sunlight's reddening between texels near the horizon).
TEST_F(BrunetonGLTest, OneOrderIsSingleScattering) {
  struct Case {
    const char* scene;
    double max_relative;
  };
  for (const Case& c : {Case{"earth_noon", 0.012}, Case{"earth_sunset", 0.08},
                        Case{"mars_noon", 0.005}}) {
    Scene scene = find_scene(c.scene, 32, 16);
    ImageRGB single = render_scene_with(scene, "bruneton:bruneton2017,orders=1,floats=full");
    ImageRGB march = render_scene_with(scene, "raymarch:fine");
    TechniqueAccuracy difference = measure_accuracy(scene, single, march);
    const auto& sky = difference.sky_channels;
    std::printf("%s: bruneton orders=1 against raymarch:fine, open sky %.2f%% %.2f%% %.2f%%\n",
                c.scene, 100 * sky[0].relative(), 100 * sky[1].relative(), 100 * sky[2].relative());
    for (int k = 0; k < 3; ++k) EXPECT_LT(sky[k].relative(), c.max_relative) << c.scene << k;
  }
}

std::vector<float> scattering_texels(const BrunetonTechnique& technique) {
  const BrunetonTechnique::Settings& s = technique.settings();
  std::vector<float> texels(size_t(s.nu) * s.mu_s * s.mu * s.r * 4);
  glGetTextureImage(technique.scattering_table(), 0, GL_RGBA, GL_FLOAT,
                    GLsizei(texels.size() * sizeof(float)), texels.data());
  return texels;
}

TEST_F(BrunetonGLTest, CorruptCacheIsReportedAndRebuilt) {
  Scene scene = find_scene("asteroid_surface", 32, 16);
  AtmosphereModel model = scene_atmosphere(scene, scene_body(scene));
  BrunetonTechnique::Settings settings = small_settings();
  settings.orders = 3;  // a key no other test uses
  std::filesystem::path file;
  std::vector<float> built;
  {
    BrunetonTechnique first(settings);
    file = bruneton_cache_file(first.cache_key(model));
    std::filesystem::remove(file);
    first.update(model);
    EXPECT_FALSE(first.from_cache());
    ASSERT_TRUE(std::filesystem::exists(file));
    // What the lab counts its tables' disk by: the file less its header.
    uintmax_t bytes = std::filesystem::file_size(file);
    EXPECT_GE(bytes, BrunetonTechnique::table_file_bytes(settings));
    EXPECT_LE(bytes, BrunetonTechnique::table_file_bytes(settings) + 256);
    EXPECT_EQ(first.precompute_seconds().size(), size_t(settings.orders)) << "one time per order";
    built = scattering_texels(first);
  }
  {
    BrunetonTechnique second(settings);
    second.update(model);
    EXPECT_TRUE(second.from_cache()) << "the tables were not read back from " << file;
    EXPECT_EQ(0, std::memcmp(built.data(), scattering_texels(second).data(),
                             built.size() * sizeof(float)));
  }
  // One byte in the middle of the tables flipped: the checksum fails.
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    ASSERT_TRUE(f);
    f.seekg(0, std::ios::end);
    std::streamoff middle = f.tellg() / 2;
    f.seekg(middle);
    char byte = 0;
    f.read(&byte, 1);
    byte = char(byte ^ 0x5a);
    f.seekp(middle);
    f.write(&byte, 1);
  }
  testing::internal::CaptureStderr();
  BrunetonTechnique third(settings);
  third.update(model);
  std::string said = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(third.from_cache()) << "a corrupt file was used";
  EXPECT_NE(said.find(file.filename().string()), std::string::npos)
      << "the corrupt file was not named: " << said;
  EXPECT_EQ(0, std::memcmp(built.data(), scattering_texels(third).data(),
                           built.size() * sizeof(float)))
      << "the rebuilt tables differ from the first build";
  // The rebuilt file is whole again.
  BrunetonTechnique fourth(settings);
  fourth.update(model);
  EXPECT_TRUE(fourth.from_cache());
}

// fly builds the tables a slice at a time between its frames: with a
// frame's worth of other state between the slices (other textures on the
// units the passes read, other images, another program and atmosphere
// block), they are the same bytes as the tables built in one go.
TEST_F(BrunetonGLTest, TablesBuiltInSlicesAreTheSameBytes) {
  Scene scene = find_scene("earth_noon", 32, 16);
  AtmosphereModel model = scene_atmosphere(scene, scene_body(scene));
  BrunetonTechnique::Settings settings = small_settings();
  settings.orders = 4;  // the tail too; a key no other test uses
  std::vector<float> at_once;
  {
    BrunetonTechnique first(settings);
    std::filesystem::remove(bruneton_cache_file(first.cache_key(model)));
    first.update(model);
    ASSERT_FALSE(first.from_cache());
    at_once = scattering_texels(first);
  }
  BrunetonTechnique sliced(settings);
  std::filesystem::remove(bruneton_cache_file(sliced.cache_key(model)));
  std::unique_ptr<TableBuild> build = sliced.update_in_slices(model);
  Texture other_2d = make_texture_2d(GL_RGBA32F, 4, 4);
  Texture other_3d = make_texture_3d(GL_RGBA32F, 4, 4, 4);
  const float big[4] = {1e3f, 1e3f, 1e3f, 1e3f};
  glClearTexImage(other_2d.id(), 0, GL_RGBA, GL_FLOAT, big);
  glClearTexImage(other_3d.id(), 0, GL_RGBA, GL_FLOAT, big);
  Buffer other_block = make_buffer(4096, nullptr);
  int slices = 0;
  double fraction = 0;
  while (!build->step()) {
    ++slices;
    EXPECT_GE(build->fraction(), fraction) << "after slice " << slices;
    fraction = build->fraction();
    for (GLuint unit = 0; unit < 6; ++unit) {
      glBindTextureUnit(unit, unit % 2 ? other_3d.id() : other_2d.id());
      glBindImageTexture(unit, other_3d.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, other_block.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, other_block.id());
    glUseProgram(0);
  }
  EXPECT_FALSE(sliced.from_cache());
  EXPECT_EQ(build->fraction(), 1.0);
  // A layer of the 3D table a slice: single scattering, each order's
  // density and light, the tail.
  EXPECT_GE(slices, settings.r * (2 + 2 * (settings.orders - 1)));
  std::vector<float> in_slices = scattering_texels(sliced);
  ASSERT_EQ(at_once.size(), in_slices.size());
  EXPECT_EQ(0, std::memcmp(at_once.data(), in_slices.data(), at_once.size() * sizeof(float)))
      << "the tables built in slices differ from those built at once";
}

// The lab's floor lifts the default limit, never one the environment set.
TEST(BrunetonCacheLimit, AFloorLiftsTheDefaultButNotTheEnvironments) {
  const char* was = std::getenv("PLANET_BRUNETON_CACHE_MB");
  std::string saved = was ? was : "";
  const uintmax_t mb = 1024 * 1024;
  unsetenv("PLANET_BRUNETON_CACHE_MB");
  EXPECT_EQ(bruneton_cache_limit_bytes(), 4096 * mb);
  set_bruneton_cache_floor(5000 * mb);
  EXPECT_EQ(bruneton_cache_limit_bytes(), 5000 * mb);
  EXPECT_FALSE(bruneton_cache_limit_from_environment());
  setenv("PLANET_BRUNETON_CACHE_MB", "100", 1);
  EXPECT_EQ(bruneton_cache_limit_bytes(), 100 * mb);
  EXPECT_TRUE(bruneton_cache_limit_from_environment());
  set_bruneton_cache_floor(0);
  if (was) {
    setenv("PLANET_BRUNETON_CACHE_MB", saved.c_str(), 1);
  } else {
    unsetenv("PLANET_BRUNETON_CACHE_MB");
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
