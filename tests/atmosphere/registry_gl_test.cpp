// The registry of techniques: every name and quality point parses and reads
// back, `name:key=value` reaches the technique it names, and the default
// quality written out is the default.
#include "atmosphere/gpu/registry.h"

#include "core/data_paths.h"
#include "core/error.h"
#include "gl/context.h"
#include "render/frame.h"

#include "tests/render/view_from_place.h"

#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(TechniqueRegistryTest, EveryQualityPointParsesAndReadsBack) {
  for (const TechniqueEntry& t : technique_registry()) {
    TechniqueChoice defaults = parse_technique(t.name);
    EXPECT_EQ(defaults.text(), t.name) << "the defaults read back as the bare name";
    ASSERT_EQ(defaults.values.size(), t.quality.size());
    for (size_t i = 0; i < t.quality.size(); ++i) {
      EXPECT_EQ(defaults.values[i].second, t.quality[i].default_value) << t.name;
      EXPECT_GE(t.quality[i].default_value, t.quality[i].min) << t.name << " " << t.quality[i].key;
      EXPECT_LE(t.quality[i].default_value, t.quality[i].max) << t.name << " " << t.quality[i].key;
    }
    EXPECT_GE(t.quality_points.size(), 3u) << t.name << ": cheap to expensive";
    for (const auto& [point, settings] : t.quality_points) {
      std::string text = settings.empty() ? t.name : t.name + ":" + settings;
      TechniqueChoice choice = parse_technique(text);
      EXPECT_EQ(parse_technique(choice.text()).values, choice.values) << text;
      // By its name, as the lab and a user name it.
      EXPECT_EQ(parse_technique(t.name + ":" + point).values, choice.values) << point;
    }
  }
}

TEST(TechniqueRegistryTest, KeysAfterAQualityPointChangeIt) {
  TechniqueChoice c = parse_technique("bruneton:cheap,orders=3");
  EXPECT_EQ(c.integer("r_size"), 16);
  EXPECT_EQ(c.integer("orders"), 3);
  EXPECT_EQ(parse_technique("raymarch:fine").integer("view_steps"), 128);
  EXPECT_THROW(parse_technique("raymarch:finest"), InputError);
}

TEST(TechniqueRegistryTest, ValuesAreCheckedAgainstTheirRanges) {
  TechniqueChoice c = parse_technique("hillaire:per_pixel_steps=20,path=luts");
  EXPECT_EQ(c.integer("per_pixel_steps"), 20);
  EXPECT_EQ(c.integer("path"), 1);
  EXPECT_EQ(c.text(), "hillaire:per_pixel_steps=20,path=luts");
  EXPECT_THROW(parse_technique("hillaire:per_pixel_steps=3"), InputError);
  EXPECT_THROW(parse_technique("hillaire:per_pixel_steps=1e9"), InputError);
  EXPECT_THROW(parse_technique("hillaire:per_pixel_steps=nan"), InputError);
  EXPECT_THROW(parse_technique("hillaire:per_pixel_steps="), InputError);
  EXPECT_THROW(parse_technique("hillaire:=4"), InputError);
  EXPECT_THROW(parse_technique("hillaire:"), InputError);
  EXPECT_THROW(parse_technique("hillaire:path=2"), InputError);
  EXPECT_THROW(parse_technique("Hillaire"), InputError);
}

// The quality reaches the shader: the default written out draws the same
// bits as the bare name, and fewer steps draw something else.
TEST(TechniqueRegistryGLTest, QualityInTheNameReachesTheTechnique) {
  auto context = GlContext::create_headless();
  Body body = load_body(data_dir() / "planets" / "earth.json");
  body.terrain = nullptr;
  AtmosphereModel model = load_atmosphere(body);
  auto view = view_from_place(body.shape, {glm::radians(46.5), glm::radians(8.0), 2.0}, 0.0, 10.0,
                              90.0, 20.0, 180.0);
  auto draw = [&](const std::string& technique) {
    FrameRenderer renderer(32, 32);
    renderer.set_body(body, model, make_technique(technique));
    renderer.render(view.camera, view.sun_dir_body, 10.0);
    return renderer.read_hdr();
  };
  std::vector<float> plain = draw("raymarch");
  EXPECT_EQ(draw("raymarch:view_steps=32,light_steps=16"), plain);
  EXPECT_NE(draw("raymarch:view_steps=4"), plain);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
