// Bruneton's functions (atmosphere/shaders/bruneton_functions.glsl)
// compiled as C++ in double, as the shared math is (shared_math.cpp), and on
// the GPU (llvmpipe compute, float): the tables' parameterisations agree to
// what float arithmetic allows. The functions that read a table are left to
// the technique's image tests (bruneton_gl_test.cpp): on the CPU their
// texture() throws, since no table is sampled there.
#include "atmosphere/gpu/atmosphere_block.h"
#include "atmosphere/math/shared_math.h"
#include "gl/context.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "sim/body.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

// The file as C++, in the shared math's namespace (it calls the shared
// functions), with external linkage: the functions no test calls must not
// warn as unused ones of an anonymous namespace would.
namespace planet::shared {

using namespace glm;
using Real4 = glm::dvec4;
struct Table2D {};
struct Table3D {};
Real4 texture(const Table2D&, const Real2&) { throw std::logic_error("no CPU table"); }
Real4 texture(const Table3D&, const Real3&) { throw std::logic_error("no CPU table"); }
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
// clang-format off
#include "atmosphere/shaders/bruneton_functions.glsl"
// clang-format on
#undef IN
#undef OUT
#undef INOUT

// The tables' sizes of the test (the technique's defaults; the GPU's come as
// defines), and a smallest sun zenith cosine exact in float.
constexpr BrunetonSizes kTestSizes{256, 64, 64, 16, 32, 128, 32, 8, -0.25};
BrunetonSizes bruneton_sizes() { return kTestSizes; }

}  // namespace planet::shared

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(BrunetonFunctionsGLTest, GpuFloatAgreesWithCpuDouble) {
  auto context = GlContext::create_headless();
  const shared::BrunetonSizes& s = shared::kTestSizes;
  Program program = Program::compute(
      "tests/atmosphere/bruneton_functions_probe.comp",
      {fmt::format("TRANSMITTANCE_WIDTH {}", s.transmittance_width),
       fmt::format("TRANSMITTANCE_HEIGHT {}", s.transmittance_height),
       fmt::format("IRRADIANCE_WIDTH {}", s.irradiance_width),
       fmt::format("IRRADIANCE_HEIGHT {}", s.irradiance_height),
       fmt::format("SCATTERING_R {}", s.r), fmt::format("SCATTERING_MU {}", s.mu),
       fmt::format("SCATTERING_MU_S {}", s.mu_s), fmt::format("SCATTERING_NU {}", s.nu)});
  // Earth's shell, its radii exact in float so that both sides start equal.
  AtmosphereModel model = load_atmosphere(load_body(find_body_file("earth")));
  model.bottom_radius = double(float(model.bottom_radius));
  model.top_radius = double(float(model.top_radius));
  const shared::Atmosphere a = shared::to_shared(model);
  const AtmosphereBlock block = make_atmosphere_block(model);
  // Inputs exact in float, away from the horizon (whose side float and
  // double may tell apart).
  std::vector<glm::vec4> inputs;
  for (float h : {1.0f, 1000.0f, 25000.0f, 59000.0f}) {
    for (float mu : {-0.5f, -0.25f, 0.125f, 0.5f, 0.875f, 1.0f}) {
      for (float mu_s : {-0.125f, 0.0625f, 0.5f, 1.0f}) {
        float nu = std::clamp(mu * mu_s + 0.25f, -1.0f, 1.0f);
        inputs.emplace_back(float(model.bottom_radius) + h, mu, mu_s, nu);
      }
    }
  }
  Buffer uniforms = make_buffer(sizeof(block), &block);
  Buffer in = make_buffer(inputs.size() * sizeof(glm::vec4), inputs.data());
  Buffer out = make_buffer(inputs.size() * 4 * sizeof(glm::vec4), nullptr);
  program.use();
  glUniform1f(program.uniform("u_mu_s_min"), float(s.mu_s_min));
  glUniform1i(program.uniform("u_count"), GLint(inputs.size()));
  glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, uniforms.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  glDispatchCompute(GLuint((inputs.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> gpu(inputs.size() * 4);
  glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());
  check_gl_errors("bruneton functions probe");

  double worst_coordinate = 0, worst_cosine = 0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    double r = inputs[i].x, mu = inputs[i].y, mu_s = inputs[i].z, nu = inputs[i].w;
    std::string where = fmt::format("r {} mu {} mu_s {} nu {}", r, mu, mu_s, nu);
    const glm::vec4* o = &gpu[4 * i];
    bool ground = shared::ray_intersects_ground(a, r, mu);
    ASSERT_EQ(ground, o[2].x == 1.0f) << where;
    glm::dvec4 uvwz = shared::bruneton_uvwz_from_r_mu_mu_s_nu(a, r, mu, mu_s, nu, ground);
    for (int c = 0; c < 4; ++c) {
      worst_coordinate = std::max(worst_coordinate, std::abs(uvwz[c] - double(o[0][c])));
    }
    double r2, mu2, mu_s2, nu2;
    bool ground2;
    shared::bruneton_r_mu_mu_s_nu_from_uvwz(a, uvwz, r2, mu2, mu_s2, nu2, ground2);
    EXPECT_EQ(ground2, o[2].y == 1.0f) << where;
    // The cosines back from the coordinates from 1 km up: 1 m above the
    // ground a downward ray's distance to the ground (2 m at mu -0.5) is
    // 5e-4 of the mu coordinate's range there (rho, 3.6 km), so float's
    // 1e-5 in the coordinate moves it some percent, and mu came back 0.065
    // off (measured) while the coordinates agreed to 4e-5.
    if (r - a.bottom_radius >= 1000.0) {
      worst_cosine = std::max({worst_cosine, std::abs(mu2 - double(o[1].y)),
                               std::abs(mu_s2 - double(o[1].z)), std::abs(nu2 - double(o[1].w))});
    }
    EXPECT_NEAR(r2, o[1].x, 4.0) << where;
    double d = shared::bruneton_distance_to_boundary(a, r, mu, ground);
    EXPECT_NEAR(d, o[2].z, 16.0 + 1e-5 * d) << where;
    double unit = shared::bruneton_unit_from_mu_s(a, mu_s);
    worst_coordinate = std::max(worst_coordinate, std::abs(unit - double(o[2].w)));
    glm::dvec2 uv = shared::bruneton_irradiance_uv_from_r_mu_s(a, r, mu_s);
    worst_coordinate = std::max(
        {worst_coordinate, std::abs(uv.x - double(o[3].x)), std::abs(uv.y - double(o[3].y))});
    worst_cosine =
        std::max(worst_cosine, std::abs(shared::bruneton_mu_s_from_unit(a, unit) - double(o[3].z)));
    double t = shared::bruneton_ray_sample(r, mu, d, 7, 20);
    EXPECT_NEAR(t, o[3].w, 16.0 + 1e-5 * t) << where;
  }
  std::printf("worst GPU vs CPU: table coordinate %.3g, cosine %.3g\n", worst_coordinate,
              worst_cosine);
  // The shared math's bounds for its tables' coordinates
  // (shared_math_gl_test.cpp): 1e-4 of the unit range, 2e-3 in a cosine.
  // Measured: 3.7e-5 and 5.6e-5.
  EXPECT_LT(worst_coordinate, 1e-4);
  EXPECT_LT(worst_cosine, 2e-3);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
