// The same shared functions on the GPU (llvmpipe compute, float) and on the
// CPU (C++ double): they must agree to what float arithmetic allows.
#include "atmosphere/math/shared_math.h"
#include "gl/context.h"
#include "gl/program.h"
#include "gl/texture.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(SharedMathGLTest, GpuFloatAgreesWithCpuDouble) {
  auto context = GlContext::create_headless();
  Program program = Program::compute("tests/atmosphere/shared_math_probe.comp");
  const double bottom = 6360e3, top = 6460e3, g = 0.8;
  // Inputs exactly representable in float, so both sides start equal.
  std::vector<glm::vec4> inputs;
  for (float h : {0.0f, 1.0f, 1000.0f, 25000.0f, 99000.0f}) {
    for (float mu : {-0.3f, -0.05f, 0.0f, 0.02f, 0.25f, 0.5f, 0.875f, 1.0f}) {
      for (float H : {8000.0f, 1200.0f}) {
        float nu = std::sin(mu * 3.7f + h * 1e-4f);
        inputs.emplace_back(float(bottom) + h, mu, H, nu);
      }
    }
  }
  Buffer in = make_buffer(inputs.size() * sizeof(glm::vec4), inputs.data());
  Buffer out = make_buffer(inputs.size() * 4 * sizeof(glm::vec4), nullptr);
  program.use();
  glUniform4f(program.uniform("u_shell"), float(bottom), float(top), float(g), 1.0f);
  glUniform1i(program.uniform("u_count"), GLint(inputs.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  glDispatchCompute(GLuint((inputs.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> gpu(inputs.size() * 4);
  glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());
  check_gl_errors("shared math probe");

  shared::Atmosphere a{};
  a.bottom_radius = bottom;
  a.top_radius = top;
  a.mie_g = g;
  a.mie_phase_hg = 1.0;  // the model's Mie phase: Henyey-Greenstein
  // Tolerances. A float carries 24 bits (6e-8 relative): radii near 6.4e6 m
  // hold 0.5 m steps. Distances from the boundary formulas subtract squares
  // of radii, and a ray-sphere hit at distance q from the point of closest
  // approach turns an error dp in that point's radius into R dp / q: about
  // 20x for the grazing ground rays here (measured: 9.5 m). So distances
  // agree to 16 m plus 1e-5 relative, not to 1e-7. The optical depth
  // multiplies exp() of altitude / H, whose argument carries the 0.5 m
  // steps (4e-4 of a 1.2 km scale height; measured 2e-4): 1e-3 relative.
  // Phase functions and erfcx are smooth expressions of numbers near 1:
  // 1e-5 relative. The LUT coordinates and the (r, mu) round trip come from
  // the distances: 1e-4 of the unit range, 2e-3 in mu.
  auto close = [](double cpu, double gpu_value, double rel, double abs_tol) {
    return std::abs(cpu - gpu_value) <= rel * std::abs(cpu) + abs_tol;
  };
  double worst_depth = 0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    double r = inputs[i].x, mu = inputs[i].y, H = inputs[i].z, nu = inputs[i].w;
    std::string where = fmt::format("r {} mu {} H {} nu {}", r, mu, H, nu);
    const glm::vec4* o = &gpu[4 * i];
    EXPECT_TRUE(close(shared::distance_to_top_boundary(a, r, mu), o[0].x, 1e-5, 16.0)) << where;
    EXPECT_TRUE(close(shared::distance_to_bottom_boundary(a, r, mu), o[0].y, 1e-5, 16.0)) << where;
    if (!shared::ray_intersects_ground(a, r, mu)) {
      double depth = shared::exponential_optical_depth_to_top(a, H, r, mu);
      worst_depth = std::max(worst_depth, std::abs(depth - o[0].z) / depth);
      EXPECT_TRUE(close(depth, o[0].z, 1e-3, 0.0)) << where << ": " << depth << " vs " << o[0].z;
      glm::dvec2 uv = shared::transmittance_uv_from_r_mu(a, r, mu, glm::dvec2(256, 64));
      EXPECT_TRUE(close(uv.x, o[2].x, 0.0, 1e-4)) << where;
      EXPECT_TRUE(close(uv.y, o[2].y, 0.0, 1e-4)) << where;
      EXPECT_TRUE(close(r, o[2].z, 1e-6, 4.0)) << where;
      EXPECT_TRUE(close(mu, o[2].w, 0.0, 2e-3)) << where;
    }
    EXPECT_TRUE(close(shared::erfcx(std::abs(nu) * 10.0), o[0].w, 1e-5, 0.0)) << where;
    EXPECT_TRUE(close(shared::rayleigh_phase(nu), o[1].x, 1e-5, 0.0)) << where;
    EXPECT_TRUE(close(shared::henyey_greenstein_phase(g, nu), o[1].y, 1e-5, 0.0)) << where;
    EXPECT_TRUE(close(shared::cornette_shanks_phase(g, nu), o[1].z, 1e-5, 0.0)) << where;
    EXPECT_TRUE(close(shared::isotropic_phase(), o[1].w, 1e-6, 0.0));
    EXPECT_TRUE(close(shared::mie_phase(a, nu), o[3].w, 1e-5, 0.0)) << where;
    EXPECT_TRUE(close(shared::henyey_greenstein_phase(g, nu), o[3].w, 1e-5, 0.0)) << where;
    double t0, t1;
    glm::dvec3 origin(0, 0, r), d(std::sqrt(std::max(1.0 - mu * mu, 0.0)), 0, mu);
    bool hit = shared::ray_shell(origin, d, bottom, top, t0, t1);
    EXPECT_EQ(hit, o[3].x == 1.0f) << where;
    if (hit) {
      EXPECT_TRUE(close(t0, o[3].y, 1e-5, 16.0)) << where;
      EXPECT_TRUE(close(t1, o[3].z, 1e-5, 16.0)) << where << ": " << t1 << " vs " << o[3].z;
    }
  }
  std::printf("worst relative optical depth difference GPU vs CPU: %.3g\n", worst_depth);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
