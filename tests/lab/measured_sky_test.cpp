// The measured skies' loader (lab/measured_sky.h): the shipped captures
// against values read by hand from their files, the unit conversions, and
// one failing case per rule of the layout.
#include "lab/measured_sky.h"
#include "lab/measured_comparison.h"
#include "core/data_paths.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

std::filesystem::path day() { return data_dir() / "measured" / "kider-2013-05-27"; }
std::filesystem::path first_capture() { return day() / "2013-05-27___09.30.00"; }

TEST(MeasuredSkyTest, TheShippedDayHasEightCapturesOfEightyOneDirections) {
  std::vector<MeasuredCapture> captures = load_measured_day(day());
  ASSERT_EQ(captures.size(), 8u);
  EXPECT_EQ(captures.front().local, "09:30");
  EXPECT_EQ(captures.back().local, "11:15");
  for (const MeasuredCapture& c : captures) {
    ASSERT_EQ(c.directions.size(), 81u);
    EXPECT_EQ(c.first_nm, 350);
    EXPECT_EQ(c.last_nm, 830);
  }
  // Local EDT is UTC - 4 h.
  EXPECT_EQ(captures.front().utc, "2013-05-27T13:30:00Z");
  EXPECT_EQ(captures.back().utc, "2013-05-27T15:15:00Z");
}

TEST(MeasuredSkyTest, ValuesAsTheFilesHaveThem) {
  MeasuredCapture c = load_measured_capture(first_capture());
  const MeasuredDirection& zenith = c.zenith();
  EXPECT_EQ(zenith.index, 80);
  EXPECT_EQ(zenith.elevation_deg, 90.0);
  // "550\t 2.98698619008064E-02" in ..._-_80____0.0___90.0.asd.rad.txt, W m^-2 sr^-1 nm^-1.
  EXPECT_DOUBLE_EQ(zenith.radiance[550 - 350], 2.98698619008064E-02);
  // The 10 nm bin about 550 nm: the mean of 545-554 nm, read by hand.
  EXPECT_NEAR(c.band_radiance(zenith, 550.0), 2.992773e-2, 1e-8);
  // The names' azimuth runs counterclockwise from north: 112.5 there is
  // 247.5 clockwise.
  EXPECT_EQ(c.directions[10].azimuth_deg, 247.5);
  EXPECT_NEAR(c.directions[10].elevation_deg, 12.1151, 1e-12);
  // Sample 0 is the mean of samples 1 and 31 (0.0543438605964184 and
  // 0.0615413188934326 at 550 nm).
  EXPECT_NEAR(c.directions[0].radiance[200], 0.0579425897449255, 1e-15);
  EXPECT_EQ(c.repaired, std::vector<int>{0});
}

TEST(MeasuredSkyTest, LuminanceOfAFlatSpectrum) {
  // 683 lm/W times the integral of y-bar over 360-830 nm (106.857 nm at
  // 1 nm steps of the CIE 1931 table).
  std::vector<double> flat(830 - 350 + 1, 1.0);
  EXPECT_NEAR(luminance_cd_m2(flat, 350), 683.0 * 106.857, 0.002 * 683.0 * 106.857);
  // Outside 360-830 nm counts for nothing.
  std::vector<double> ultraviolet(10, 1.0);
  EXPECT_EQ(luminance_cd_m2(ultraviolet, 340), 0.0);
}

TEST(MeasuredSkyTest, TheSkysAxisOfSymmetryIsFoundNearTheSun) {
  // A sky made symmetric about 100 degrees: every ring's radiance a
  // function of the angle to that azimuth.
  MeasuredCapture c = load_measured_capture(first_capture());
  for (MeasuredDirection& d : c.directions) {
    double off = std::cos((d.azimuth_deg - 100.0) * 3.14159265358979 / 180.0);
    for (double& v : d.radiance) v = 1.0 + off + 0.01 * d.elevation_deg;
  }
  EXPECT_NEAR(symmetry_azimuth_deg(c, 110.0), 100.0, 0.11);
}

TEST(MeasuredSkyTest, ScoresSplitTheAureoleFromTheRestOfTheSky) {
  // Two directions of a flat measured sky, 0.1 W m^-2 sr^-1 nm^-1: one 5 deg
  // from the sun (modelled 0.13: 30 mW off), one far from it (0.11: 10 mW
  // off), at 360 and 370 nm.
  MeasuredCapture c;
  c.first_nm = 350;
  c.last_nm = 830;
  std::vector<double> flat(481, 0.1);
  c.directions = {{0, 100.0, 45.0, flat}, {1, 280.0, 30.0, flat}};
  SkySpectra model;
  model.radiance = {{0.13, 0.13}, {0.11, 0.11}};
  MeasuredScore s = score_against(c, model, {360.0, 370.0}, 50.0, 100.0);
  EXPECT_NEAR(s.rmse, std::sqrt((30.0 * 30.0 + 10.0 * 10.0) / 2.0), 1e-9);
  EXPECT_NEAR(s.rmse_away_from_sun, 10.0, 1e-9);
  EXPECT_NEAR(s.near_sun_share, 900.0 / 1000.0, 1e-12);
  EXPECT_EQ(s.samples, 4);
  EXPECT_EQ(s.away_samples, 2);
  EXPECT_NEAR(s.mean_measured, 100.0, 1e-9);
}

// A copy of the first capture, changed by `edit`, loaded: the message.
std::string error_after(const std::function<void(const std::filesystem::path&)>& edit) {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "planet_measured_test" / "2013-05-27___09.30.00";
  std::filesystem::remove_all(dir.parent_path());
  std::filesystem::create_directories(dir.parent_path());
  std::filesystem::copy(first_capture(), dir);
  edit(dir);
  try {
    load_measured_capture(dir);
  } catch (const InputError& e) {
    std::string message = e.what();
    size_t at = message.find("planet_measured_test/");
    return at == std::string::npos ? message : message.substr(at + 21);
  }
  return "(no error)";
}

std::filesystem::path sample(const std::filesystem::path& dir, const std::string& tail) {
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::string name = e.path().filename().string();
    if (name.find(tail) != std::string::npos) return e.path();
  }
  return {};
}

TEST(MeasuredSkyTest, EveryRuleOfTheLayoutIsChecked) {
  EXPECT_EQ(error_after([](const auto& d) { std::filesystem::remove(sample(d, "_-_7____")); }),
            "2013-05-27___09.30.00: sample 7 of 0-80 is missing (80 found)");
  EXPECT_EQ(error_after([](const auto& d) {
              std::ofstream(sample(d, "_-_5____"), std::ios::app) << "831\tnot-a-number\n";
            }),
            "2013-05-27___09.30.00/2013-05-27___09.30.00_-_5____56.25___12.1151.asd.rad.txt:483: "
            "expected \"<wavelength nm> <radiance>\", got \"831\tnot-a-number\"");
  EXPECT_EQ(error_after([](const auto& d) {
              std::ofstream(sample(d, "_-_5____"), std::ios::app) << "840\t0.1\n";
            }),
            "2013-05-27___09.30.00/2013-05-27___09.30.00_-_5____56.25___12.1151.asd.rad.txt:483: "
            "wavelength 840 nm where 831 nm was expected (1 nm steps)");
  EXPECT_EQ(error_after([](const auto& d) {
              std::ofstream(d / "2013-05-27___09.30.00_-_5____56.25___12.1151.asd.rad.txt",
                            std::ios::trunc)
                  << "Wavelength\tx\n350\t0.1\n351\t0.1\n";
            }),
            "2013-05-27___09.30.00/2013-05-27___09.30.00_-_5____56.25___12.1151.asd.rad.txt: "
            "the spectrum covers 350-351 nm; 360-830 nm is needed");
  EXPECT_EQ(error_after([](const auto& d) {
              std::filesystem::copy_file(sample(d, "_-_5____"),
                                         d / "2013-05-27___09.30.00_-_5____0.0___33.749.asd.rad.txt");
            }),
            "2013-05-27___09.30.00: sample 5 appears twice");
  EXPECT_EQ(error_after([](const auto& d) {
              std::filesystem::copy_file(sample(d, "_-_5____"), d / "sample_x.asd.rad.txt");
            }),
            "2013-05-27___09.30.00/sample_x.asd.rad.txt: not a measured sample's name "
            "(DATE___HH.MM.SS_-_INDEX____AZIMUTH___ELEVATION.asd.rad.txt)");
  EXPECT_THROW(load_measured_day(data_dir() / "planets"), InputError);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
