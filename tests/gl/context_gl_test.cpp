#include "gl/context.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(ContextGLTest, HeadlessCoreContextWithComputeShaders) {
  auto context = GlContext::create_headless();
  EXPECT_GE(epoxy_gl_version(), 45) << context->version();
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  GLint groups = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groups);
  EXPECT_GT(groups, 0);
  check_gl_errors("context test");
}

TEST(ContextGLTest, DriverErrorsBecomeExceptions) {
  auto context = GlContext::create_headless();
  glBindTexture(GL_TEXTURE_2D, 123456);  // not a texture name: GL_INVALID_OPERATION
  EXPECT_THROW(check_gl_errors("bad bind"), std::runtime_error);
  EXPECT_NO_THROW(check_gl_errors("after"));
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
