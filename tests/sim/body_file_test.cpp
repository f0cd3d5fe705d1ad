// Which file a body's name or path on the command line means.
#include "sim/body.h"

#include "core/data_paths.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

// Run in a folder that holds a folder named `mars` (a capture's output,
// say): `--planet mars` still means the shipped Mars, not that folder.
TEST(BodyFileTest, AFolderOfTheBodysNameIsNotTheBodyFile) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "planet_body_file_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "mars");
  std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  std::filesystem::path found = find_body_file("mars");
  std::string error;
  try {
    find_body_file("no_such_body_here");
  } catch (const InputError& e) {
    error = e.what();
  }
  std::filesystem::create_directories(dir / "nowhere");
  std::string folder_error;
  try {
    find_body_file("nowhere");
  } catch (const InputError& e) {
    folder_error = e.what();
  }
  std::filesystem::current_path(cwd);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(found, data_dir() / "planets" / "mars.json");
  EXPECT_NE(error.find("no such body file"), std::string::npos) << error;
  EXPECT_NE(folder_error.find("nowhere: a folder, not a body file"), std::string::npos)
      << folder_error;
}

// A path to a file still wins over the shipped names.
TEST(BodyFileTest, APathToAFileIsThatFile) {
  std::filesystem::path file = data_dir() / "planets" / "moon.json";
  EXPECT_EQ(find_body_file(file.string()), file);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
