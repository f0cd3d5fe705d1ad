#include "gl/context.h"
#include "gl/timer.h"

#include <epoxy/gl.h>
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <string>

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

// A call the GL refuses: 123456 names no texture (GL_INVALID_OPERATION).
void bind_a_texture_that_does_not_exist() { glBindTexture(GL_TEXTURE_2D, 123456); }

// The same inside a timed pass, as a frame's passes run.
void bind_it_in_a_pass() {
  GpuTimer timer;
  timer.begin("the_bad_pass");
  bind_a_texture_that_does_not_exist();
  timer.end();
  timer.collect();
}

TEST(ContextGLTest, DriverErrorsBecomeExceptions) {
  auto context = GlContext::create_headless();
  EXPECT_NONFATAL_FAILURE(bind_a_texture_that_does_not_exist(), "glBindTexture");
  EXPECT_THROW(check_gl_errors("bad bind"), std::runtime_error);
  EXPECT_NO_THROW(check_gl_errors("after"));
}

// In the test programs a GL error fails the test whose call made it, at
// the call, whether or not the code goes on to check_gl_errors(); the
// failure names the GL function and the pass it ran in.
TEST(ContextGLTest, AGlErrorFailsTheTestThatMadeItNamingTheCallAndThePass) {
  auto context = GlContext::create_headless();
  EXPECT_NONFATAL_FAILURE(bind_a_texture_that_does_not_exist(),
                          "GL_INVALID_OPERATION in glBindTexture");
  EXPECT_NONFATAL_FAILURE(bind_it_in_a_pass(), "in pass the_bad_pass");
  // Kept for check_gl_errors() too, as the program meets them.
  EXPECT_THROW(check_gl_errors("the deliberate errors"), std::runtime_error);
}

// A software driver's shaders run in threads it starts with the context:
// they flush denormal floats to zero, as GPUs do, while the thread that
// made the context keeps its own mode (the CPU's code is unchanged).
TEST(ContextGLTest, SoftwareShadersFlushDenormalsAndTheCallingThreadKeepsThem) {
  auto context = GlContext::create_headless();
  volatile float tiny = 1e-20f;
  EXPECT_GT(tiny * tiny, 0.0f) << "this thread keeps denormals";
  if (context->renderer().find("llvmpipe") == std::string::npos) {
    GTEST_SKIP() << "a GPU's driver keeps its own mode: " << context->renderer();
  }
  const char* source =
      "#version 450\n"
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = 0) buffer Out { float v[2]; };\n"
      "uniform float u_tiny;\n"
      "void main() { v[0] = u_tiny * u_tiny; v[1] = u_tiny; }\n";
  GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  ASSERT_TRUE(linked);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  const float start[2] = {-1.0f, -1.0f};
  glNamedBufferStorage(buffer, sizeof(start), start, 0);
  glUseProgram(program);
  glUniform1f(glGetUniformLocation(program, "u_tiny"), 1e-20f);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  float out[2] = {-1.0f, -1.0f};
  glGetNamedBufferSubData(buffer, 0, sizeof(out), out);
  EXPECT_FLOAT_EQ(out[1], 1e-20f) << "the shader ran";
  EXPECT_EQ(out[0], 0.0f) << "1e-40, a denormal, flushed";
  glDeleteBuffers(1, &buffer);
  glDeleteProgram(program);
  glDeleteShader(shader);
  check_gl_errors("denormals test");
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
