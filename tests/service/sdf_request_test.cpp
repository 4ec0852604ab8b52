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
  // X([0,1]^2) spans [0,1]^3, padded by 1e-3 of its largest side.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(answer.box[i], -0.001) << i;
    EXPECT_DOUBLE_EQ(answer.box[i + 3], 1.001) << i;
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

}  // namespace
}  // namespace implicitizer
