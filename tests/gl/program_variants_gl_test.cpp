// One program's variants in one table: each compiled from the table's
// defines when first asked for, and once.
#include "gl/program_variants.h"

#include "gl/context.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

ProgramVariants probe_variants() {
  return ProgramVariants("gl/shaders/fullscreen.vert", "gl/shaders/depth_probe.frag", {"COMMON 1"},
                         {{"plain", {}}, {"marked", {"MARKED 1", "MORE 2"}}});
}

TEST(ProgramVariantsTest, AVariantsDefinesAreTheProgramsThenItsOwn) {
  ProgramVariants variants = probe_variants();
  EXPECT_EQ(variants.defines("plain"), (std::vector<std::string>{"COMMON 1"}));
  EXPECT_EQ(variants.defines("marked"),
            (std::vector<std::string>{"COMMON 1", "MARKED 1", "MORE 2"}));
  EXPECT_THROW(variants.defines("missing"), std::logic_error);
  EXPECT_THROW(ProgramVariants("a.vert", "b.frag", {}, {{"twice", {}}, {"twice", {"X 1"}}}),
               std::logic_error);
}

TEST(ProgramVariantsGLTest, EachVariantIsCompiledWhenFirstAskedForAndOnce) {
  auto context = GlContext::create_headless();
  ProgramVariants variants = probe_variants();
  EXPECT_FALSE(variants.compiled("marked"));
  const GLuint first = variants["marked"].id();
  EXPECT_NE(first, 0u);
  EXPECT_TRUE(variants.compiled("marked"));
  EXPECT_FALSE(variants.compiled("plain"));
  EXPECT_EQ(variants["marked"].id(), first);
  EXPECT_NE(variants["plain"].id(), first);
  EXPECT_THROW(variants["missing"], std::logic_error);
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
