#include "implicitizer/sdf/glsl_export.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using testing::glslang_errors;
using testing::parse_xyz;

constexpr const char* kEs300 = "#version 300 es\nprecision highp float;";
constexpr const char* kGlsl330 = "#version 330";

void expect_compiles(const Polynomial& f, const SdfParams& options) {
  const std::string glsl = sdf_glsl(f, options);
  EXPECT_EQ(glsl.find("pow"), std::string::npos);
  EXPECT_NE(glsl.find("float " + options.name + "_sdf(vec3 p)"), std::string::npos);
  EXPECT_EQ(glslang_errors(kEs300, glsl, options.name + "_sdf"), "") << glsl.substr(0, 2000);
  EXPECT_EQ(glslang_errors(kGlsl330, glsl, options.name + "_sdf"), "");
}

TEST(SdfGlsl, SphereCompilesInBothDialects) {
  expect_compiles(parse_xyz("x^2+y^2+z^2-1"), SdfParams{SdfMode::fast, SceneBox::default_box(), "sphere"});
}

TEST(SdfGlsl, TorusCompilesInBothDialects) {
  expect_compiles(parse_xyz("x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9"),
                  SdfParams{SdfMode::fast, testing::box_of("-3", "-3", "-1", "3", "3", "1"), "torus"});
}

TEST(SdfGlsl, SteinerSurfaceCompilesInBothDialects) {
  expect_compiles(parse_xyz("x^2*y^2+y^2*z^2+z^2*x^2-x*y*z"), SdfParams{SdfMode::fast, SceneBox::default_box(), "steiner"});
}

TEST(SdfGlsl, Degree18Tp33CompilesInBothDialects) {
  expect_compiles(testing::tp33_implicit(),
                  SdfParams{SdfMode::fast, testing::box_of("-8", "-10", "-18", "8", "6", "4"), "tp_33"});
}

TEST(SdfGlsl, DefinesOnlyTheFunction) {
  const std::string glsl = sdf_glsl(parse_xyz("x^2+y^2+z^2-1"), SdfParams{});
  // One function definition: the first '(' after a type at line start is ours.
  std::size_t functions = 0;
  for (std::size_t at = glsl.find("\nfloat "); at != std::string::npos; at = glsl.find("\nfloat ", at + 1)) {
    ++functions;
  }
  EXPECT_EQ(functions, 1u);
  EXPECT_EQ(glsl.find("uniform"), std::string::npos);
  EXPECT_NE(glsl.find("float surface_sdf(vec3 p)"), std::string::npos);
}

TEST(SdfGlsl, SafeSphereTorusAndSteinerCompileInBothDialects) {
  expect_compiles(parse_xyz("x^2+y^2+z^2-1"), SdfParams{SdfMode::safe, SceneBox::default_box(), "sphere"});
  expect_compiles(parse_xyz("x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9"),
                  SdfParams{SdfMode::safe, testing::box_of("-3", "-3", "-1", "3", "3", "1"), "torus"});
  expect_compiles(parse_xyz("x^2*y^2+y^2*z^2+z^2*x^2-x*y*z"),
                  SdfParams{SdfMode::safe, SceneBox::default_box(), "steiner"});
  expect_compiles(parse_xyz("1e-30*((x-1e-3)^2+(y-2*1e-3)^2+(z+1e-3)^2-1e-12)"),
                  SdfParams{SdfMode::safe,
                             testing::box_of("0.999e-3", "1.999e-3", "-1.001e-3", "1.001e-3", "2.001e-3", "-0.999e-3"),
                             "tiny"});
}

TEST(SdfGlsl, SafeDegree18Tp33CompilesInBothDialects) {
  expect_compiles(testing::tp33_implicit(),
                  SdfParams{SdfMode::safe, testing::box_of("-8", "-10", "-18", "8", "6", "4"), "tp_33"});
}

TEST(SdfGlsl, SafeModeDefinesOnlyTheFunction) {
  const std::string glsl = sdf_glsl(parse_xyz("x^2+y^2+z^2-1"), SdfParams{SdfMode::safe, SceneBox::default_box(), "a"});
  std::size_t functions = 0;
  for (std::size_t at = glsl.find("\nfloat "); at != std::string::npos; at = glsl.find("\nfloat ", at + 1)) {
    ++functions;
  }
  EXPECT_EQ(functions, 1u);
  EXPECT_EQ(glsl.find("uniform"), std::string::npos);
  EXPECT_NE(glsl.find("float a_sdf(vec3 p)"), std::string::npos);
  EXPECT_NE(glsl.find("safe distance bound"), std::string::npos);
}

TEST(SdfGlsl, ParsesModesAndRefusesOthers) {
  EXPECT_EQ(parse_sdf_mode("fast"), SdfMode::fast);
  EXPECT_EQ(parse_sdf_mode("safe"), SdfMode::safe);
  try {
    (void)parse_sdf_mode("Fast");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "invalid_value");
    EXPECT_EQ(e.field(), "mode");
  }
  // Mode safe refuses what fp32 cannot bound (SafeSdf::build).
  try {
    (void)sdf_glsl(parse_xyz("x^60+y"), SdfParams{SdfMode::safe, SceneBox::default_box(), "a"});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "degree_too_high");
  }
}

TEST(SdfGlsl, ValidatesTheNameBeforeAnythingElse) {
  EXPECT_THROW((void)sdf_glsl(parse_xyz("x"), SdfParams{SdfMode::fast, SceneBox::default_box(), "a(){}; void b"}),
               InputError);
  // Issue 16: "gl" itself is an identifier, but the function would be gl_sdf.
  EXPECT_THROW((void)sdf_glsl(parse_xyz("x"), SdfParams{SdfMode::fast, SceneBox::default_box(), "gl"}), InputError);
}

}  // namespace
}  // namespace implicitizer
