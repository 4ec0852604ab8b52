#include "implicitizer/sdf/glsl_name.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/sdf/glsl_export.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

std::string refusal(const std::string& name) {
  try {
    check_glsl_name(name);
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "invalid_name") << name;
    EXPECT_EQ(e.field(), "name") << name;
    return e.what();
  }
  return "";
}

TEST(GlslName, AcceptsIdentifiers) {
  for (const char* name :
       {"a", "sphere", "Tp_33", "_x", "surface2", "floats", "glx_y", "GL", "Gl", "g", "gl0", "_gl"}) {
    EXPECT_NO_THROW(check_glsl_name(name)) << name;
  }
  EXPECT_NO_THROW(check_glsl_name(std::string(64, 'a')));
}

TEST(GlslName, RefusesInjectionsReservedNamesAndKeywords) {
  for (const std::string& name : std::vector<std::string>{
           "",      "a(){}; void b", "a b",         "a;",        "a\n#define x", "1a",
           "a-b",   "gl_X",          "gl_Position", "a__b",      "__a",          "a_",
           "float", "void",          "uniform",     "highp",     "precision",    "vec3",
           "true",  "struct",        "return",      "sampler2D", "main\xc3\xa9", std::string(65, 'a')}) {
    EXPECT_NE(refusal(name), "") << "accepted '" << name << "'";
  }
}

// Issue 16: a scene named "gl" passed, and its GLSL defined gl_sdf and gl_sphere,
// which glslangValidator rejects. The name is valid alone; what it derives is not.
TEST(GlslName, RefusesNamesWhoseDerivedIdentifiersAreReserved) {
  EXPECT_NE(refusal("gl").find("gl_sdf"), std::string::npos) << refusal("gl");
  EXPECT_NE(refusal("gl").find("reserves"), std::string::npos) << refusal("gl");
  EXPECT_NE(refusal("a_").find("a__sdf"), std::string::npos) << refusal("a_");
}

// The other side of the rule: names next to the reserved ones are accepted, and the
// GLSL made from them compiles (fast and safe modes).
TEST(GlslName, AcceptedNamesNextToTheReservedOnesCompile) {
  const Polynomial sphere = testing::parse_xyz("x^2+y^2+z^2-1");
  for (const char* name : {"GL", "Gl", "g", "gl0", "_gl", "glx_y"}) {
    for (const SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      const std::string glsl = sdf_glsl(sphere, SdfParams{mode, SceneBox::default_box(), name});
      for (const char* header : {"#version 300 es\nprecision highp float;", "#version 330"}) {
        EXPECT_EQ(testing::glslang_errors(header, glsl, std::string(name) + "_sdf"), "") << name << "\n" << glsl;
      }
    }
  }
}

}  // namespace
}  // namespace implicitizer
