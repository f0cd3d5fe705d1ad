// The cloud field and phase on the GPU (llvmpipe compute, float) and on
// the CPU (the same GLSL as C++ in double): the same cloud to what float
// arithmetic allows.
#include "clouds/cloud_model.h"
#include "clouds/gpu/cloud_pass.h"
#include "gl/context.h"
#include "gl/program.h"
#include "gl/texture.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

TEST(CloudDensityGLTest, GpuFloatAgreesWithCpuDouble) {
  auto context = GlContext::create_headless();
  Program program = Program::compute("tests/clouds/cloud_density_probe.comp");
  const double bottom = 6360e3;
  std::optional<CloudModel> model = load_clouds(load_body(find_body_file("earth")));
  ASSERT_TRUE(model);
  shared::CloudLayer layer = to_shared(*model, bottom);
  // Points through the layer and a little outside it, over the globe, as
  // floats (exact on both sides); 4096 of them.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::vec4> inputs;
  while (inputs.size() < 4096) {
    double z = 2.0 * u(rng) - 1.0, phi = 2.0 * 3.141592653589793 * u(rng);
    double s = std::sqrt(1.0 - z * z);
    double r =
        layer.bottom_radius - 300.0 + (layer.top_radius - layer.bottom_radius + 600.0) * u(rng);
    inputs.emplace_back(float(r * s * std::cos(phi)), float(r * s * std::sin(phi)), float(r * z),
                        float(2.0 * u(rng) - 1.0));
  }
  Buffer in = make_buffer(inputs.size() * sizeof(glm::vec4), inputs.data());
  Buffer out = make_buffer(inputs.size() * sizeof(glm::vec4), nullptr);
  program.use();
  const std::array<float, 12> block = cloud_layer_uniforms(layer);
  glUniform4fv(program.uniform("u_layer"), 3, block.data());
  glUniform1i(program.uniform("u_count"), GLint(inputs.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  glDispatchCompute(GLuint((inputs.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> gpu(inputs.size());
  glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());
  check_gl_errors("cloud density probe");

  // The CPU reads the same floats the GPU read: the layer as floats too.
  shared::CloudLayer cpu_layer = layer;
  cpu_layer.bottom_radius = block[0];
  cpu_layer.top_radius = block[1];
  // Tolerances. A position near 6.4e6 m holds 0.5 m steps in float; the
  // shape noise's cells are 9 km and the erosion's 1.2 km, so a lattice
  // coordinate carries about 1e-3 of a cell of rounding (p / scale in
  // float), which a noise of slope near 1 a cell turns into 1e-3, and the
  // remaps (by up to 1 / (1 - lo)) into a few 1e-3 of density (measured:
  // 1.6e-3). Hence 5e-3 absolute on the density; the weather's cells are
  // 250 km: 1e-4 (measured 1e-5). The phase is a smooth function of nu:
  // 1e-4 relative (measured 7e-5).
  double worst_density = 0, worst_weather = 0, worst_phase = 0;
  int cloudy = 0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    glm::dvec3 p(inputs[i].x, inputs[i].y, inputs[i].z);
    double nu = inputs[i].w;
    double density = shared::cloud_density(cpu_layer, p);
    glm::dvec2 weather = shared::cloud_weather(cpu_layer, p);
    double phase = shared::cloud_phase(cpu_layer.droplet_diameter_um, nu);
    if (density > 0) ++cloudy;
    worst_density = std::max(worst_density, std::abs(density - gpu[i].x));
    worst_weather = std::max(worst_weather, std::abs(weather.x - gpu[i].y));
    worst_weather = std::max(worst_weather, std::abs(weather.y - gpu[i].z));
    worst_phase = std::max(worst_phase, std::abs(phase - gpu[i].w) / phase);
    std::string where = fmt::format("p ({}, {}, {}) nu {}", p.x, p.y, p.z, nu);
    EXPECT_NEAR(density, gpu[i].x, 5e-3) << where;
    EXPECT_NEAR(weather.x, gpu[i].y, 1e-4) << where;
    EXPECT_NEAR(weather.y, gpu[i].z, 1e-4) << where;
    EXPECT_NEAR(phase, gpu[i].w, 1e-4 * phase) << where;
  }
  // The points must see clouds, or the test checks nothing.
  EXPECT_GT(cloudy, 200);
  std::printf(
      "%d of %zu points in cloud; worst GPU vs CPU: density %.3g, weather %.3g, phase %.3g "
      "relative\n",
      cloudy, inputs.size(), worst_density, worst_weather, worst_phase);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
