// The std140 block, the atmosphere's form on the GPU: make_atmosphere_block
// puts every field of the model where the C++ mirror says
// (AtmosphereFormsTest, no GL), the GLSL block has the mirror's layout, and
// block_atmosphere() (atmosphere/shaders/atmosphere_block.glsl) unpacks it
// into the shared Atmosphere the CPU makes of the same model, field by
// field (AtmosphereFormsGLTest). The structured bindings name every field
// of the block and of the shared Atmosphere: a field added to either fails
// to compile here until it is checked.
#include "atmosphere/gpu/atmosphere_block.h"
#include "atmosphere/math/shared_math.h"
#include "gl/context.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "tests/atmosphere/distinct_atmosphere.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

using forms::distinct_model;

glm::vec4 block_vec(const glm::dvec3& v, float w = 0.0f) { return glm::vec4(glm::vec3(v), w); }

TEST(AtmosphereFormsTest, EveryModelFieldReachesTheBlock) {
  for (MiePhase phase : {MiePhase::kCornetteShanks, MiePhase::kHenyeyGreenstein}) {
    const AtmosphereModel m = distinct_model(phase);
    // The model's fields; wavelengths_nm and spectrum reach no shader.
    const auto& [bottom_radius, top_radius, wavelengths_nm, solar_irradiance, sun_angular_radius,
                 mie_g, mie_phase, ground_albedo, rayleigh, mie, absorber, spectrum] = m;
    const auto& [b_radii, b_solar_irradiance, b_rayleigh_scattering, b_mie_scattering,
                 b_mie_extinction, b_absorption_extinction, b_ground_albedo, b_layer_a, b_layer_b] =
        make_atmosphere_block(m);
    EXPECT_EQ(b_radii, glm::vec4(float(bottom_radius), float(top_radius), float(mie_g),
                                 float(sun_angular_radius)));
    EXPECT_EQ(b_solar_irradiance, block_vec(solar_irradiance));
    EXPECT_EQ(b_rayleigh_scattering, block_vec(rayleigh.scattering));
    EXPECT_EQ(b_mie_scattering, block_vec(mie.scattering));
    EXPECT_EQ(b_mie_extinction, block_vec(mie.scattering + mie.absorption));
    EXPECT_EQ(b_absorption_extinction, block_vec(absorber.scattering + absorber.absorption));
    // w: the Mie phase function, 0 Cornette-Shanks, 1 Henyey-Greenstein.
    EXPECT_EQ(b_ground_albedo,
              block_vec(ground_albedo, mie_phase == MiePhase::kHenyeyGreenstein ? 1.0f : 0.0f));
    const AtmosphereComponent* components[3] = {&rayleigh, &mie, &absorber};
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 2; ++k) {
        const DensityLayer& l = components[i]->density.layers[k];
        EXPECT_EQ(b_layer_a[2 * i + k], glm::vec4(float(l.width), float(l.exp_term),
                                                  float(l.exp_scale), float(l.linear_term)))
            << components[i]->name << " layer " << k;
        EXPECT_EQ(b_layer_b[2 * i + k], glm::vec4(float(l.constant_term), 0.0f, 0.0f, 0.0f))
            << components[i]->name << " layer " << k;
      }
    }
  }
}

// The shared Atmosphere's fields in the struct's order (definitions.glsl),
// named, in float: what atmosphere_block_probe.comp writes.
std::vector<std::pair<std::string, float>> flatten(const shared::Atmosphere& a) {
  const auto& [bottom_radius, top_radius, solar_irradiance, sun_angular_radius, rayleigh_scattering,
               rayleigh_density, mie_scattering, mie_extinction, mie_g, mie_density,
               absorption_extinction, absorption_density, ground_albedo, mie_phase_hg] = a;
  std::vector<std::pair<std::string, float>> out;
  auto put = [&](const std::string& name, double x) { out.emplace_back(name, float(x)); };
  auto put3 = [&](const std::string& name, const glm::dvec3& v) {
    for (int c = 0; c < 3; ++c) put(name + "[" + std::to_string(c) + "]", v[c]);
  };
  auto put_profile = [&](const std::string& name, const shared::DensityProfile& p) {
    for (int k = 0; k < 2; ++k) {
      const auto& [width, exp_term, exp_scale, linear_term, constant_term] = p.layers[k];
      std::string layer = name + ".layers[" + std::to_string(k) + "].";
      put(layer + "width", width);
      put(layer + "exp_term", exp_term);
      put(layer + "exp_scale", exp_scale);
      put(layer + "linear_term", linear_term);
      put(layer + "constant_term", constant_term);
    }
  };
  put("bottom_radius", bottom_radius);
  put("top_radius", top_radius);
  put3("solar_irradiance", solar_irradiance);
  put("sun_angular_radius", sun_angular_radius);
  put3("rayleigh_scattering", rayleigh_scattering);
  put_profile("rayleigh_density", rayleigh_density);
  put3("mie_scattering", mie_scattering);
  put3("mie_extinction", mie_extinction);
  put("mie_g", mie_g);
  put_profile("mie_density", mie_density);
  put3("absorption_extinction", absorption_extinction);
  put_profile("absorption_density", absorption_density);
  put3("ground_albedo", ground_albedo);
  put("mie_phase_hg", mie_phase_hg);
  return out;
}

GLint program_resource(GLuint program, GLenum interface, const char* name, GLenum property) {
  GLuint index = glGetProgramResourceIndex(program, interface, name);
  EXPECT_NE(index, GL_INVALID_INDEX) << name;
  GLint value = -1;
  glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
  return value;
}

TEST(AtmosphereFormsGLTest, TheShaderUnpacksTheBlockIntoTheModelsSharedAtmosphere) {
  auto context = GlContext::create_headless();
  Program program = Program::compute("tests/atmosphere/atmosphere_block_probe.comp");
  // The GLSL block's layout, as the driver lays it out, is the C++ mirror's.
  const GLuint id = program.id();
  EXPECT_EQ(program_resource(id, GL_UNIFORM_BLOCK, "AtmosphereBlock", GL_BUFFER_DATA_SIZE),
            GLint(sizeof(AtmosphereBlock)));
  EXPECT_EQ(program_resource(id, GL_UNIFORM_BLOCK, "AtmosphereBlock", GL_BUFFER_BINDING),
            GLint(kAtmosphereBlockBinding));
  const std::pair<const char*, size_t> members[] = {
      {"u_radii", offsetof(AtmosphereBlock, radii)},
      {"u_solar_irradiance", offsetof(AtmosphereBlock, solar_irradiance)},
      {"u_rayleigh_scattering", offsetof(AtmosphereBlock, rayleigh_scattering)},
      {"u_mie_scattering", offsetof(AtmosphereBlock, mie_scattering)},
      {"u_mie_extinction", offsetof(AtmosphereBlock, mie_extinction)},
      {"u_absorption_extinction", offsetof(AtmosphereBlock, absorption_extinction)},
      {"u_ground_albedo", offsetof(AtmosphereBlock, ground_albedo)},
      {"u_layer_a[0]", offsetof(AtmosphereBlock, layer_a)},
      {"u_layer_b[0]", offsetof(AtmosphereBlock, layer_b)}};
  for (const auto& [name, offset] : members) {
    EXPECT_EQ(program_resource(id, GL_UNIFORM, name, GL_OFFSET), GLint(offset)) << name;
  }
  for (const char* array : {"u_layer_a[0]", "u_layer_b[0]"}) {
    EXPECT_EQ(program_resource(id, GL_UNIFORM, array, GL_ARRAY_STRIDE), GLint(sizeof(glm::vec4)));
    EXPECT_EQ(program_resource(id, GL_UNIFORM, array, GL_ARRAY_SIZE), 6);
  }

  // And what the shader reads from it is the model's shared Atmosphere, in
  // float: each field in its place, for both phase functions.
  for (MiePhase phase : {MiePhase::kCornetteShanks, MiePhase::kHenyeyGreenstein}) {
    const AtmosphereModel m = distinct_model(phase);
    const AtmosphereBlock block = make_atmosphere_block(m);
    const std::vector<std::pair<std::string, float>> expected = flatten(shared::to_shared(m));
    Buffer uniforms = make_buffer(sizeof(block), &block);
    Buffer out = make_buffer(expected.size() * sizeof(float), nullptr);
    program.use();
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereBlockBinding, uniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> gpu(expected.size());
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
    check_gl_errors("atmosphere block probe");
    for (size_t i = 0; i < expected.size(); ++i) {
      EXPECT_EQ(gpu[i], expected[i].second) << expected[i].first << ", " << to_string(phase);
    }
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
