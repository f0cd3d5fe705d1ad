// The "clouds" object of a body's file: the shipped values, and one clear
// error naming the file and the field for each bad one.
#include "clouds/cloud_model.h"
#include "core/data_paths.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

nlohmann::json earth_clouds() {
  std::ifstream in(data_dir() / "planets" / "earth.json");
  return nlohmann::json::parse(in)["clouds"];
}

// Parses Earth's clouds changed by `edit` and returns the error message.
std::string error_after(const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json c = earth_clouds();
  edit(c);
  try {
    parse_clouds(JsonObject(c, "bad.json", "clouds"), 100e3);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CloudModelTest, EarthHasWaterCloudsAndMarsThinIceClouds) {
  std::optional<CloudModel> earth = load_clouds(load_body(find_body_file("earth")));
  ASSERT_TRUE(earth);
  EXPECT_EQ(earth->bottom_altitude, 1500.0);
  EXPECT_EQ(earth->top_altitude, 6000.0);
  EXPECT_EQ(earth->droplet_diameter_um, 20.0);
  std::optional<CloudModel> mars = load_clouds(load_body(find_body_file("mars")));
  ASSERT_TRUE(mars);
  // Thin: a full column at full density is an optical depth below 1.
  EXPECT_LT(mars->extinction * (mars->top_altitude - mars->bottom_altitude), 1.0);
  shared::CloudLayer l = to_shared(*earth, 6360e3);
  EXPECT_EQ(l.bottom_radius, 6361.5e3);
  EXPECT_EQ(l.top_radius, 6366e3);
  EXPECT_EQ(l.seed, 7.0);
}

TEST(CloudModelTest, NoCloudsObjectNoClouds) {
  EXPECT_FALSE(load_clouds(load_body(find_body_file("moon"))));
  EXPECT_FALSE(load_clouds(load_body(find_body_file("asteroid"))));
  EXPECT_FALSE(load_clouds(load_body(find_body_file("earth_kider_2013"))));
}

TEST(CloudModelTest, BadValuesNameTheFileAndTheField) {
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["extinction_per_m"] = -0.04; }),
            "bad.json: clouds.extinction_per_m: -0.04 is out of range [0, 1]");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["top_altitude_m"] = 1000.0; }),
            "bad.json: clouds.top_altitude_m: 1000 m must be above bottom_altitude_m (1500 m)");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["top_altitude_m"] = 200e3; }),
            "bad.json: clouds.top_altitude_m: 200000 is out of range [0, 100000]");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["weather"]["type"] = "satellite"; }),
            "bad.json: clouds.weather.type: 'satellite' is not a known weather (procedural)");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["weather"]["coverage"] = 1.5; }),
            "bad.json: clouds.weather.coverage: 1.5 is out of range [0, 1]");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["droplet_diameter_um"] = 0.5; }),
            "bad.json: clouds.droplet_diameter_um: 0.5 is out of range [1.5, 50]");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["weather"]["seed"] = 2.5; }),
            "bad.json: clouds.weather.seed: must be a whole number");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c.erase("erosion"); }),
            "bad.json: clouds.erosion: missing");
  EXPECT_EQ(error_after([](nlohmann::json& c) { c["albedo"] = 1.0; }),
            "bad.json: clouds.albedo: unknown key");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
