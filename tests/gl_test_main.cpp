// main() of the GL tests: driver debug output becomes errors, so any GL
// error a test provokes fails it, and what techniques cache (precomputed
// tables) goes into the build tree, not the user's cache. (CTest's per-test
// ENVIRONMENT cannot carry two variables through gtest_discover_tests,
// hence here.) The shipped references are read from data/reference.
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  setenv("PLANET_GL_DEBUG", "1", 1);
  setenv("PLANET_CACHE_DIR", PLANET_TEST_CACHE_DIR, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
