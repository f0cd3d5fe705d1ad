// main() of the GL tests: driver debug output is on, and a GL error (or a
// message of high severity) fails the test whose call made it, at the call,
// naming the call and its pass (gl/debug_output.h); what techniques cache
// (precomputed tables) goes into the build tree, not the user's cache.
// (CTest's per-test ENVIRONMENT cannot carry two variables through
// gtest_discover_tests, hence here.) The shipped references are read from
// data/reference.
#include "gl/debug_output.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace {

void fail_the_test(const std::string& report) { ADD_FAILURE() << "GL: " << report; }

}  // namespace

int main(int argc, char** argv) {
  setenv("PLANET_GL_DEBUG", "1", 1);
  setenv("PLANET_CACHE_DIR", PLANET_TEST_CACHE_DIR, 1);
  planet::set_gl_error_handler(fail_the_test);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
