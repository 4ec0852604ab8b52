// Tests of server/service/src/sdf_request.cpp: every input compiles as a scene, and
// the answer reports the box actually used, the dimension and the shape picked.

#include "implicitizer/service/sdf_request.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

TEST(AnswerSdfRequest, AnImplicitSurfaceIsAOneLeafScene) {
  SdfRequest r;
  r.implicit = "x^2+y^2+z^2-1";
  r.name = "ball";
  const CompiledSdfRequest compiled = compile_sdf_request(r);
  EXPECT_EQ(compiled.scene.node_count(), 1u);
  const SdfAnswer answer = describe_sdf_request(compiled);
  EXPECT_EQ(answer.function, "ball_sdf");
  EXPECT_NE(answer.glsl.find("float ball_sdf(vec3 p)"), std::string::npos);
  EXPECT_EQ(answer.dimension, 3);
  EXPECT_EQ(answer.box, (std::array<double, 6>{-2, -2, -2, 2, 2, 2}));
  EXPECT_EQ(answer.degree, 2);
  // An input is not a scene: no nodes, no leaves (the fields of scenes only).
  EXPECT_EQ(answer.nodes, 0u);
  EXPECT_TRUE(answer.leaves.empty());
  // The sphere is closed inside its box: a solid under auto, negative inside.
  ASSERT_TRUE(answer.shape.has_value());
  EXPECT_EQ(*answer.shape, SdfShape::solid);
  EXPECT_LT(compiled.scene.evaluate<float>({0.0F, 0.0F, 0.0F}), 0.0F);
  EXPECT_GT(compiled.scene.evaluate<float>({2.0F, 0.0F, 0.0F}), 0.5F);
}

TEST(AnswerSdfRequest, APatchWithoutABoxGetsTheFittedBoxAndIsASheet) {
  SdfRequest r;
  r.parametric = std::array<std::string, 3>{"s", "t", "s*t"};
  r.domain = {"0", "1", "0", "1"};
  const SdfAnswer answer = answer_sdf_request(r);
  // X([0,1]^2) spans [0,1]^3, padded by 1e-4 of its largest side.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(answer.box[i], -0.0001) << i;
    EXPECT_DOUBLE_EQ(answer.box[i + 3], 1.0001) << i;
  }
  ASSERT_TRUE(answer.shape.has_value());
  EXPECT_EQ(*answer.shape, SdfShape::sheet);
  EXPECT_EQ(answer.degree, 2);
  // A box the request gives is the box used.
  r.box = {"-1", "-1", "-1", "2", "2", "2"};
  EXPECT_EQ(answer_sdf_request(r).box, (std::array<double, 6>{-1, -1, -1, 2, 2, 2}));
}

TEST(AnswerSdfRequest, ASceneReportsItsLeavesAndItsBox) {
  SdfRequest r;
  r.scene = make_node(NodeKind::csg_union, {}, {make_node(NodeKind::sphere, {{"radius", 1.0}}), SceneNode{}});
  r.scene->children[1].kind = NodeKind::implicit;
  r.scene->children[1].leaf.equation = "x^2+y^2+z^2-4";
  r.box = {"-3", "-3", "-3", "3", "3", "3"};
  const SdfAnswer answer = answer_sdf_request(r);
  EXPECT_EQ(answer.nodes, 3u);
  ASSERT_EQ(answer.leaves.size(), 1u);
  EXPECT_EQ(answer.leaves[0].shape, SdfShape::solid);
  EXPECT_FALSE(answer.shape.has_value());  // a scene of several nodes: each leaf says its own
  EXPECT_EQ(answer.box, (std::array<double, 6>{-3, -3, -3, 3, 3, 3}));
}

TEST(AnswerSdfRequest, ErrorsNameTheRequestsFields) {
  auto error = [](const SdfRequest& r) {
    const InputError e = input_error_of([&] { answer_sdf_request(r); });
    return e.code() + "@" + e.field();
  };
  SdfRequest r;
  r.implicit = "x^60+y";
  r.mode = SdfMode::safe;
  EXPECT_EQ(error(r), "degree_too_high@implicit");
  r.mode = SdfMode::fast;
  r.implicit = "x+w";
  EXPECT_EQ(error(r), "unknown_variable@implicit");
  r.implicit = "3";
  EXPECT_EQ(error(r), "constant_polynomial@implicit");
  r.implicit = "x";
  r.name = "gl_x";
  EXPECT_EQ(error(r), "invalid_name@name");
  r = SdfRequest{};
  r.parametric = std::array<std::string, 3>{"s", "t", "s*q^"};
  EXPECT_EQ(error(r).substr(error(r).find('@')), "@z");
  r.parametric = std::array<std::string, 3>{"s", "t", "s*t"};
  r.domain = {"0", "1", "0"};
  EXPECT_EQ(error(r), "invalid_domain@domain");
  r.domain = {"0", "1", "1", "1"};
  EXPECT_EQ(error(r), "invalid_domain@domain[2]");
  // A parametrization whose image is not a surface is NoSingleEquation, with its ideal.
  r = SdfRequest{};
  r.parametric = std::array<std::string, 3>{"t", "t^2", "t^3"};
  try {
    answer_sdf_request(r);
    ADD_FAILURE() << "no NoSingleEquation";
  } catch (const NoSingleEquation& e) {
    EXPECT_EQ(e.generators().size(), 3u);
  }
}

// Issue 18's semantics, computed by the library (lib/scene: shapes, curves).

TEST(AnswerSdfRequest, AutoPicksASheetForAnOpenSurface) {
  SdfRequest r;
  r.implicit = "z-x*y";  // the saddle meets every face of its box
  const CompiledSdfRequest saddle = compile_sdf_request(r);
  const SdfAnswer answer = describe_sdf_request(saddle);
  ASSERT_TRUE(answer.shape.has_value());
  EXPECT_EQ(*answer.shape, SdfShape::sheet);
  // A sheet is >= 0 everywhere, on both sides of the surface.
  for (const Vec3<float>& p : {Vec3<float>{0.5F, 0.5F, 1.5F}, Vec3<float>{0.5F, 0.5F, -1.5F},
                               Vec3<float>{-1.0F, 0.2F, 0.0F}, Vec3<float>{3.0F, 3.0F, 3.0F}}) {
    EXPECT_GE(saddle.scene.evaluate<float>(p), 0.0F) << p.x << " " << p.y << " " << p.z;
  }
  // The plane z = 0 as a sheet is |z| (F/|grad F| = z exactly); as a solid, z.
  r.implicit = "z";
  const CompiledSdfRequest plane = compile_sdf_request(r);
  EXPECT_EQ(describe_sdf_request(plane).shape, std::optional<SdfShape>(SdfShape::sheet));
  EXPECT_FLOAT_EQ(plane.scene.evaluate<float>({0.5F, 0.5F, -0.25F}), 0.25F);
  r.shape = SdfShape::solid;
  const CompiledSdfRequest solid = compile_sdf_request(r);
  EXPECT_EQ(describe_sdf_request(solid).shape, std::optional<SdfShape>(SdfShape::solid));
  EXPECT_FLOAT_EQ(solid.scene.evaluate<float>({0.5F, 0.5F, -0.25F}), -0.25F);
}

TEST(AnswerSdfRequest, AnEquationWithoutZIsAPlaneCurve) {
  SdfRequest r;
  r.implicit = "x^2+y^2-1";
  r.box = {"-2", "-2", "2", "2"};
  const CompiledSdfRequest circle = compile_sdf_request(r);
  const SdfAnswer answer = describe_sdf_request(circle);
  EXPECT_EQ(answer.dimension, 2);
  EXPECT_EQ(circle.scene.dimension(), 2);
  EXPECT_NE(answer.glsl.find("float surface_sdf(vec2 p)"), std::string::npos);
  // Closed inside its box: a solid. F/|grad F| = (r^2 - 1)/(2r) in the plane.
  EXPECT_EQ(answer.shape, std::optional<SdfShape>(SdfShape::solid));
  EXPECT_FLOAT_EQ(circle.scene.evaluate<float>({2.0F, 0.0F, 0.0F}), 0.75F);
  EXPECT_FLOAT_EQ(circle.scene.evaluate<float>({0.5F, 0.0F, 0.0F}), -0.75F);
}

TEST(AnswerSdfRequest, ASixNumberBoxMakesAnEquationWithoutZASurface) {
  // Issue 39: the cylinder from its own equation.
  SdfRequest r;
  r.implicit = "x^2+y^2-1";
  r.box = {"-2", "-2", "-2", "2", "2", "2"};
  const CompiledSdfRequest cylinder = compile_sdf_request(r);
  const SdfAnswer answer = describe_sdf_request(cylinder);
  EXPECT_EQ(answer.dimension, 3);
  EXPECT_NE(answer.glsl.find("float surface_sdf(vec3 p)"), std::string::npos);
  // It runs into the box's top and bottom: automatic makes it a sheet, the same
  // distance at every height, |r^2 - 1|/(2r) at r = 2 and 1/2.
  EXPECT_EQ(answer.shape, std::optional<SdfShape>(SdfShape::sheet));
  for (const float z : {-1.5F, 0.0F, 1.5F}) {
    EXPECT_FLOAT_EQ(cylinder.scene.evaluate<float>({2.0F, 0.0F, z}), 0.75F);
    EXPECT_FLOAT_EQ(cylinder.scene.evaluate<float>({0.0F, 0.5F, z}), 0.75F);
  }
  // A term with a zero coefficient changes no variable: still the plane curve without
  // a box or with four numbers, the cylinder with six.
  r.implicit = "x^2+y^2+0*z-1";
  EXPECT_EQ(answer_sdf_request(r).dimension, 3);
  r.box = {"-2", "-2", "2", "2"};
  EXPECT_EQ(answer_sdf_request(r).dimension, 2);
  r.box.clear();
  const SdfAnswer curve = answer_sdf_request(r);
  EXPECT_EQ(curve.dimension, 2);
  EXPECT_NE(curve.glsl.find("float surface_sdf(vec2 p)"), std::string::npos);
  // A z that survives is a surface whatever the box.
  r.implicit = "x^2+y^2+z-1";
  EXPECT_EQ(answer_sdf_request(r).dimension, 3);
}

TEST(AnswerSdfRequest, AParametricCurveIsTrimmedToItsDomainAndFitted) {
  SdfRequest r;
  r.parametric = std::array<std::string, 3>{"t", "t^2", ""};
  r.domain = {"-1", "1"};
  const CompiledSdfRequest parabola = compile_sdf_request(r);
  const SdfAnswer answer = describe_sdf_request(parabola);
  EXPECT_EQ(answer.dimension, 2);
  EXPECT_EQ(answer.shape, std::optional<SdfShape>(SdfShape::sheet));
  // X([-1, 1]) spans [-1, 1] x [0, 1]; padded by 1e-4 of its largest side, 2.
  EXPECT_DOUBLE_EQ(answer.box[0], -1.0002);
  EXPECT_DOUBLE_EQ(answer.box[1], -0.0002);
  EXPECT_DOUBLE_EQ(answer.box[3], 1.0002);
  EXPECT_DOUBLE_EQ(answer.box[4], 1.0002);
  EXPECT_NEAR(parabola.scene.evaluate<float>({0.5F, 0.25F, 0.0F}), 0.0F, 1e-6F);  // on the arc
  EXPECT_GT(parabola.scene.evaluate<float>({0.0F, 0.5F, 0.0F}), 0.1F);            // off it
  // A curve's domain is one interval.
  r.domain = {"-1", "1", "0", "1"};
  const InputError e = input_error_of([&] { answer_sdf_request(r); });
  EXPECT_EQ(e.code() + "@" + e.field(), "invalid_domain@domain");
}

}  // namespace
}  // namespace implicitizer
