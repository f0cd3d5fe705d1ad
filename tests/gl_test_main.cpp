// main() of the GL tests: driver debug output becomes errors, so any GL
// error a test provokes fails it. (CTest's per-test ENVIRONMENT cannot
// carry two variables through gtest_discover_tests, hence here.)
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  setenv("PLANET_GL_DEBUG", "1", 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
