#include "sim/flight_script.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <fstream>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

class FlightScriptTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("planet_flight_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    auto p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }

  // A valid script, with `replace` substituted for `find` to break it.
  std::string script(const std::string& find = "", const std::string& replace = "") {
    std::string s = R"({
      "body": "earth",
      "image": {"width": 64, "height": 32},
      "frame_rate": 2,
      "exposure": 8,
      "sun": {"elevation_deg": 30, "azimuth_deg": 120},
      "keyframes": [
        {"time": 0, "lat_deg": 10, "lon_deg": 170, "height_m": 2, "heading_deg": 90},
        {"time": 1, "lat_deg": 10, "lon_deg": -170, "height_m": 1000, "heading_deg": 90},
        {"time": 2, "lat_deg": 11, "lon_deg": -160, "height_m": 5000, "heading_deg": 95}
      ]
    })";
    if (!find.empty()) {
      auto at = s.find(find);
      EXPECT_NE(at, std::string::npos) << find;
      s.replace(at, find.size(), replace);
    }
    return s;
  }

  // Loading must throw an InputError whose message holds every fragment.
  void expect_error(const std::filesystem::path& file, std::vector<std::string> fragments) {
    try {
      load_flight_script(file);
      ADD_FAILURE() << "no error for " << file;
    } catch (const InputError& e) {
      std::string what = e.what();
      for (const auto& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << what;
    }
  }

  std::filesystem::path dir_;
};

TEST_F(FlightScriptTest, LoadsAValidScript) {
  auto s = load_flight_script(write("ok.json", script()));
  EXPECT_EQ(s.body.name, "Earth");
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.keyframes.size(), 3u);
  EXPECT_EQ(s.frame_count(), 5);  // t = 0, 0.5, 1, 1.5, 2
  EXPECT_DOUBLE_EQ(s.frame_time(3), 1.5);
  EXPECT_NEAR(glm::length(s.sun_dir_body), 1.0, 1e-12);
}

TEST_F(FlightScriptTest, CrossesTheAntimeridianTheShortWay) {
  FlightScript s = load_flight_script(write("ok.json", script()));
  FlightPath path(s);
  for (double t = 0; t <= 1.0; t += 0.05) {
    double lon = glm::degrees(path.place_at(t).lon);
    EXPECT_TRUE(lon >= 169.999 || lon <= -169.999) << t << " " << lon;
  }
}

TEST_F(FlightScriptTest, SamplesAreReproducibleAndHitKeyframes) {
  FlightScript s = load_flight_script(write("ok.json", script()));
  FlightPath a(s), b(s);
  for (int i = 0; i < s.frame_count(); ++i) {
    Camera ca = a.camera_at(s.frame_time(i)), cb = b.camera_at(s.frame_time(i));
    EXPECT_EQ(ca.pos_body, cb.pos_body);
  }
  Geodetic g = a.place_at(1.0);
  EXPECT_NEAR(g.height, 1000.0, 1e-9);
  EXPECT_NEAR(glm::degrees(g.lon), -170.0, 1e-9);
}

TEST_F(FlightScriptTest, MissingFile) {
  expect_error(dir_ / "nope.json", {"nope.json", "cannot open"});
}

TEST_F(FlightScriptTest, MalformedJson) {
  expect_error(write("bad.json", script("\"frame_rate\": 2,", "\"frame_rate\": 2")),
               {"bad.json", "malformed JSON", "line"});
}

TEST_F(FlightScriptTest, UnknownKey) {
  expect_error(write("bad.json", script("\"exposure\": 8", "\"exposur\": 8")),
               {"bad.json", "exposur", "unknown key"});
  expect_error(write("bad2.json", script("\"heading_deg\": 95", "\"headin_deg\": 95")),
               {"keyframes[2].headin_deg", "unknown key"});
}

TEST_F(FlightScriptTest, KeyframeTimeGoingBackwards) {
  expect_error(write("bad.json", script("\"time\": 2,", "\"time\": 0.5,")),
               {"bad.json", "keyframes[2].time", "does not come after"});
}

TEST_F(FlightScriptTest, ZeroImageSize) {
  expect_error(write("bad.json", script("\"width\": 64", "\"width\": 0")),
               {"image.width", "out of range"});
}

TEST_F(FlightScriptTest, AntialiasingIsFourUnlessGivenAndAPowerOfTwo) {
  EXPECT_EQ(load_flight_script(write("ok.json", script())).antialiasing, 4);
  auto with = [&](const char* value) {
    return script("\"height\": 32", std::string("\"height\": 32, \"antialiasing\": ") + value);
  };
  EXPECT_EQ(load_flight_script(write("one.json", with("1"))).antialiasing, 1);
  expect_error(write("bad.json", with("3")), {"bad.json", "image.antialiasing", "3 samples", "2, 4, 8"});
  expect_error(write("bad2.json", with("32")), {"image.antialiasing", "out of range"});
}

TEST_F(FlightScriptTest, ExposureIsANumberOrAutoAndStarsAreOnUnlessTurnedOff) {
  FlightScript fixed = load_flight_script(write("ok.json", script()));
  EXPECT_FALSE(fixed.auto_exposure);
  EXPECT_EQ(fixed.exposure, 8.0);
  EXPECT_TRUE(fixed.stars);
  const std::string automatic = script("\"exposure\": 8", "\"exposure\": \"auto\"");
  EXPECT_TRUE(load_flight_script(write("auto.json", automatic)).auto_exposure);
  FlightScript dark = load_flight_script(
      write("dark.json", script("\"height\": 32", "\"height\": 32, \"stars\": false")));
  EXPECT_FALSE(dark.stars);
  expect_error(write("bad.json", script("\"exposure\": 8", "\"exposure\": \"bright\"")),
               {"bad.json", "exposure", "\"auto\""});
  // An automatic exposure leaves the keyframes none to give.
  std::string keyed = automatic;
  const std::string first = "\"heading_deg\": 90}";
  keyed.replace(keyed.find(first), first.size(), "\"heading_deg\": 90, \"exposure\": 2}");
  expect_error(write("bad2.json", keyed), {"keyframes[0].exposure", "\"auto\""});
}

// The window's glare is a capture's only when the flight asks for it.
TEST_F(FlightScriptTest, GlareIsOffUnlessAsked) {
  EXPECT_FALSE(load_flight_script(write("ok.json", script())).glare);
  FlightScript glaring = load_flight_script(
      write("glare.json", script("\"height\": 32", "\"height\": 32, \"glare\": true")));
  EXPECT_TRUE(glaring.glare);
  expect_error(write("bad.json", script("\"height\": 32", "\"height\": 32, \"glare\": 1")),
               {"bad.json", "glare"});
}

TEST_F(FlightScriptTest, OutOfRangeLatitudeAndMissingField) {
  expect_error(write("bad.json", script("\"lat_deg\": 11", "\"lat_deg\": 91")),
               {"keyframes[2].lat_deg", "91", "out of range"});
  expect_error(write("bad2.json", script("\"frame_rate\": 2,", "")), {"frame_rate", "missing"});
  expect_error(write("bad3.json", script("\"frame_rate\": 2", "\"frame_rate\": \"fast\"")),
               {"frame_rate", "must be a number"});
}

TEST_F(FlightScriptTest, UnknownBody) {
  expect_error(write("bad.json", script("\"earth\"", "\"vulcan\"")), {"body", "vulcan"});
}

TEST_F(FlightScriptTest, BadBodyFileNamesTheBodyFileAndField) {
  auto body = write("flat.json", R"({"name": "Flat", "shape": {"type": "ellipsoid",
      "equatorial_radius_m": -5}})");
  expect_error(write("bad.json", script("\"earth\"", "\"" + body.string() + "\"")),
               {"flat.json", "shape.equatorial_radius_m", "-5", "out of range"});
  auto body2 = write("weird.json", R"({"name": "W", "shape": {"type": "torus",
      "equatorial_radius_m": 5}})");
  expect_error(write("bad2.json", script("\"earth\"", "\"" + body2.string() + "\"")),
               {"weird.json", "shape.type", "torus"});
}

// A keyframe's height is above the ellipsoid ("height_m") or above the
// ground under it ("height_above_ground_m"), here a ground 1000 m up.
TEST_F(FlightScriptTest, AHeightAboveTheGroundCountsFromTheGroundUnderTheKeyframe) {
  std::vector<Geodetic> asked;
  GroundHeight ground = [&](const Body& body, const Geodetic& place) {
    EXPECT_EQ(body.name, "Earth");
    asked.push_back(place);
    return 1000.0;
  };
  FlightScript s = load_flight_script(
      write("ok.json", script("\"height_m\": 1000,", "\"height_above_ground_m\": 2,")), ground);
  ASSERT_EQ(asked.size(), 1u);  // the one keyframe that counts from the ground
  EXPECT_NEAR(glm::degrees(asked[0].lat), 10.0, 1e-12);
  EXPECT_NEAR(glm::degrees(asked[0].lon), -170.0, 1e-12);
  const Keyframe& k = s.keyframes[1];
  EXPECT_DOUBLE_EQ(k.place.height, 1002.0);
  ASSERT_TRUE(k.height_above_ground);
  EXPECT_DOUBLE_EQ(*k.height_above_ground, 2.0);
  EXPECT_FALSE(s.keyframes[0].height_above_ground);
  // The pose is the one the same place above the ellipsoid gives.
  FlightScript same =
      load_flight_script(write("same.json", script("\"height_m\": 1000,", "\"height_m\": 1002,")));
  EXPECT_EQ(k.pos_body, same.keyframes[1].pos_body);
  EXPECT_EQ(k.body_from_camera, same.keyframes[1].body_from_camera);
}

TEST_F(FlightScriptTest, BothHeightsInOneKeyframeOrNeitherIsRefused) {
  GroundHeight ground = [](const Body&, const Geodetic&) { return 0.0; };
  auto both = write("both.json", script("\"height_m\": 1000,",
                                        "\"height_m\": 1000, \"height_above_ground_m\": 2,"));
  auto neither = write("neither.json", script("\"height_m\": 1000,", ""));
  auto expect = [&](const std::filesystem::path& file, std::vector<std::string> fragments) {
    try {
      load_flight_script(file, ground);
      ADD_FAILURE() << "no error for " << file;
    } catch (const InputError& e) {
      std::string what = e.what();
      for (const auto& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << what;
    }
  };
  expect(both, {"both.json", "keyframes[1]", "\"height_m\" (above the ellipsoid) and",
                "\"height_above_ground_m\" (above the ground) both given"});
  expect(neither, {"neither.json", "keyframes[1]", "give \"height_m\" (above the ellipsoid) or"});
  // Without a ground to count from (a reader given none), refused too.
  expect_error(
      write("no_ground.json", script("\"height_m\": 1000,", "\"height_above_ground_m\": 2,")),
      {"keyframes[1].height_above_ground_m", "no ground"});
}

TEST_F(FlightScriptTest, ALookAtTargetMayCountItsHeightFromTheGround) {
  GroundHeight ground = [](const Body&, const Geodetic&) { return 3000.0; };
  auto above_ground = write("a.json", script("\"heading_deg\": 95}",
                                             "\"look_at\": {\"lat_deg\": 12, \"lon_deg\": -160, "
                                             "\"height_above_ground_m\": 10}}"));
  auto above_ellipsoid = write(
      "b.json", script("\"heading_deg\": 95}",
                       "\"look_at\": {\"lat_deg\": 12, \"lon_deg\": -160, \"height_m\": 3010}}"));
  EXPECT_EQ(load_flight_script(above_ground, ground).keyframes[2].body_from_camera,
            load_flight_script(above_ellipsoid).keyframes[2].body_from_camera);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
