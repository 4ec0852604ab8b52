// Tests of server/codec/src/sdf_json.cpp: the decoder's choices and refusals, and the
// answer's JSON for an implicit surface and for a scene.
#include "implicitizer/codec/sdf_json.hpp"

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

TEST(AnswerSdfRequest, ModeSafeAnswersTheBound) {
  const SdfRequest request = decode_sdf_request(R"({"implicit": "x^2+y^2+z^2-1", "mode": "safe", "name": "ball"})");
  EXPECT_EQ(request.mode, SdfMode::safe);
  const SdfAnswer answer = answer_sdf_request(request);
  EXPECT_EQ(answer.mode, SdfMode::safe);
  EXPECT_EQ(answer.function, "ball_sdf");
  EXPECT_NE(answer.glsl.find("float ball_sdf(vec3 p)"), std::string::npos);
  EXPECT_NE(answer.glsl.find("safe distance bound"), std::string::npos);
  EXPECT_EQ(answer.glsl.find("pow"), std::string::npos);
  EXPECT_NE(encode_sdf_response(answer).find(R"("mode":"safe")"), std::string::npos);
  // Fast stays the default.
  EXPECT_EQ(answer_sdf_request(decode_sdf_request(R"({"implicit": "x"})")).mode, SdfMode::fast);
}

TEST(AnswerSdfRequest, ErrorsNameTheirField) {
  SdfRequest r;
  r.implicit = "x^60+y";
  r.mode = SdfMode::safe;
  const InputError degree = input_error_of([&] { answer_sdf_request(r); });
  EXPECT_EQ(degree.code(), "degree_too_high");
  EXPECT_EQ(degree.field(), "implicit");
  const InputError mode = input_error_of([] { decode_sdf_request(R"({"implicit": "x^60+y", "mode": "exact"})"); });
  EXPECT_EQ(mode.code(), "invalid_value");
  EXPECT_EQ(mode.field(), "mode");
  // One input: an implicit surface or a scene.
  const InputError both = input_error_of([&] { decode_sdf_request(R"({"implicit": "x", "scene": {}})"); });
  EXPECT_EQ(both.code(), "invalid_value");
  EXPECT_EQ(both.field(), "scene");
  const InputError neither = input_error_of([&] { decode_sdf_request(R"({"mode": "fast"})"); });
  EXPECT_EQ(neither.code(), "missing_field");
  // A scene's errors name the node's path; the request's box is the scene box.
  SdfRequest s = decode_sdf_request(R"({"scene": {"type": "union", "children": [{"type": "sphere", "radius": 1},
                                        {"type": "sphere", "radius": -1}]}})");
  const InputError radius = input_error_of([&] { answer_sdf_request(s); });
  EXPECT_EQ(radius.code(), "invalid_value");
  EXPECT_EQ(radius.field(), "scene.children[1].radius");
  s.box = {"1", "0", "0", "0", "1", "1"};
  s.scene->children[1].set("radius", 1.0);
  const InputError box = input_error_of([&] { answer_sdf_request(s); });
  EXPECT_EQ(box.code(), "invalid_box");
}

TEST(AnswerSdfRequest, SceneAnswersGlslUniformsAndLeaves) {
  const SdfRequest request = decode_sdf_request(R"({"scene": {"type": "union", "children": [
      {"type": "sphere", "radius": 1, "name": "ball", "uniforms": ["radius"]},
      {"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [0, 1]]}]},
      "mode": "safe", "name": "demo"})");
  const SdfAnswer answer = answer_sdf_request(request);
  EXPECT_EQ(answer.function, "demo_sdf");
  EXPECT_NE(answer.glsl.find("float demo_sdf(vec3 p)"), std::string::npos);
  EXPECT_EQ(answer.nodes, 3U);
  EXPECT_EQ(answer.degree, 2);
  const std::string json = encode_sdf_response(answer);
  EXPECT_NE(json.find(R"("leaves":[{"implicit":"x*y-z","degree":2,"trimmed":true,"shape":"sheet",)"
                      R"("trimming":{"method":"slabs","leaves":1,"box_leaves":0,"blunt_edge_leaves":0}}])"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find(R"("uniforms":[{"name":"ball_radius","type":"float","default":1.0}])"), std::string::npos)
      << json;
  // An implicit surface has no uniforms, and says so.
  EXPECT_NE(
      encode_sdf_response(answer_sdf_request(decode_sdf_request(R"({"implicit": "x"})"))).find(R"("uniforms":[])"),
      std::string::npos);
}

TEST(DecodeSdfRequest, ReadsTheObjectItsShapeAndDomain) {
  const SdfRequest p = decode_sdf_request(
      R"({"x": "s", "y": "t", "z": "s*t", "parameters": ["s", "t"], "shape": "sheet", "domain": [0, 1, "-1/3", 0.5],)"
      R"( "box": [-1, -1, -1, 1, 1, 1], "mode": "safe", "name": "saddle", "timeout_ms": 500})");
  ASSERT_TRUE(p.parametric.has_value());
  EXPECT_EQ(*p.parametric, (std::array<std::string, 3>{"s", "t", "s*t"}));
  EXPECT_EQ(p.parameters, (std::optional<std::vector<std::string>>{{"s", "t"}}));
  EXPECT_EQ(p.shape, SdfShape::sheet);
  // Numbers as their shortest decimal (0.5), exact strings as given.
  EXPECT_EQ(p.domain, (std::vector<std::string>{"0", "1", "-1/3", "0.5"}));
  EXPECT_EQ(p.box.size(), 6u);
  EXPECT_EQ(p.mode, SdfMode::safe);
  EXPECT_EQ(p.timeout_seconds, std::optional<double>(0.5));
  // x and y alone: a plane curve (z left empty).
  const SdfRequest curve = decode_sdf_request(R"({"x": "t", "y": "t^2", "domain": [-1, 1], "box": [-1, 0, 1, 1]})");
  EXPECT_EQ((*curve.parametric)[2], "");
  EXPECT_EQ(curve.box.size(), 4u);
  EXPECT_EQ(decode_sdf_request(R"({"implicit": "x"})").shape, SdfShape::automatic);

  auto code = [](const char* body) {
    const InputError e = input_error_of([&] { decode_sdf_request(body); });
    return e.code() + "@" + e.field();
  };
  EXPECT_EQ(code(R"({"implicit": "x", "shape": "hollow"})"), "invalid_value@shape");
  EXPECT_EQ(code(R"({"implicit": "x", "shape": true})"), "wrong_type@shape");
  EXPECT_EQ(code(R"({"x": "s", "y": "t", "domain": 1})"), "invalid_domain@domain");
  EXPECT_EQ(code(R"({"x": "s", "y": "t", "domain": [0, [1]]})"), "invalid_domain@domain[1]");
  EXPECT_EQ(code(R"({"x": "s", "y": "t", "domain": [0, 1e400]})"), "invalid_json@");
  EXPECT_EQ(code(R"({"x": "s", "z": "t"})"), "missing_field@y");
  EXPECT_EQ(code(R"({"implicit": "x", "x": "s", "y": "t"})"), "invalid_value@scene");
  EXPECT_EQ(code(R"({"implicit": "x", "dimension": 2})"), "unknown_field@dimension");
}

TEST(EncodeSdfResponse, ShapeDimensionAndTheBoxUsed) {
  SdfAnswer answer;
  answer.function = "c_sdf";
  answer.box = {-1, -2, -3, 1, 2, 3};
  answer.shape = SdfShape::sheet;
  answer.dimension = 3;
  std::string json = encode_sdf_response(answer);
  EXPECT_NE(json.find(R"("mode":"fast","shape":"sheet","dimension":3,"box":[-1.0,-2.0,-3.0,1.0,2.0,3.0],)"),
            std::string::npos)
      << json;
  // A curve's box is its plane box x0, y0, x1, y1.
  answer.dimension = 2;
  json = encode_sdf_response(answer);
  EXPECT_NE(json.find(R"("dimension":2,"box":[-1.0,-2.0,1.0,2.0],)"), std::string::npos) << json;
  // No shape for a scene of several nodes.
  answer.shape.reset();
  EXPECT_EQ(encode_sdf_response(answer).find("shape"), std::string::npos);
}

// tp_22 of ../shared/bench/surfaces_hard.json over [0, 1]^2 with `members`.
std::string tp22_request(const std::string& members) {
  return R"({"x": "3-t-2*t^2-3*s-5*s*t+5*s^2-s^2*t+4*s^2*t^2", "y": "-3+5*t-t^2-s+5*s*t-4*s*t^2+2*s^2+5*s^2*t",
             "z": "-3-3*t-4*t^2-2*s+5*s*t-3*s*t^2+3*s^2+5*s^2*t+2*s^2*t^2", "domain": [0, 1, 0, 1])" +
         members + "}";
}

// Enneper's surface over [0, 1]^2 with `members`: one low-degree piece is shorter GLSL
// than its exact equation (degree 9).
std::string enneper_request(const std::string& members) {
  return R"({"x": "s-s^3/3+s*t^2", "y": "t-t^3/3+s^2*t", "z": "s^2-t^2", "domain": [0, 1, 0, 1])" + members + "}";
}

TEST(AnswerSdfRequest, ToleranceAnswersTheApproximationAndItsBounds) {
  const SdfRequest request = decode_sdf_request(enneper_request(R"(, "tolerance": 0.01)"));
  EXPECT_EQ(request.tolerance, 0.01);
  const SdfAnswer answer = answer_sdf_request(request);
  ASSERT_TRUE(answer.approximation);
  const ApproximationSummary& a = *answer.approximation;
  EXPECT_EQ(a.tolerance, 0.01);
  EXPECT_EQ(a.kept_exact, "");
  EXPECT_GE(a.pieces, 1u);
  EXPECT_EQ(answer.degree, a.degree);
  EXPECT_LE(a.degree, 6);
  EXPECT_LE(a.patch_to_surface, 0.01);
  EXPECT_LE(a.surface_to_patch, 0.01);
  EXPECT_EQ(a.glsl_lines, count_lines(answer.glsl));
  EXPECT_EQ(answer.shape, SdfShape::sheet);
  const std::string json = encode_sdf_response(answer);
  EXPECT_NE(json.find(R"("approximation":{"tolerance":0.01,"exact":false,"degree":)"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("patch_to_surface":{"bound":)"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("glsl_lines":)" + std::to_string(a.glsl_lines)), std::string::npos) << json;
  if (a.surface_to_patch_method == BoundMethod::measured) {
    EXPECT_GT(a.surface_to_patch_samples, 0u);
    EXPECT_NE(json.find(R"("method":"measured","samples":)"), std::string::npos) << json;
  }
  // Without a tolerance the answer is the exact one, as before: no "approximation".
  const SdfAnswer exact = answer_sdf_request(decode_sdf_request(enneper_request("")));
  EXPECT_FALSE(exact.approximation);
  EXPECT_EQ(exact.degree, 9);
  EXPECT_EQ(encode_sdf_response(exact).find("approximation"), std::string::npos);
  EXPECT_LT(a.glsl_lines, count_lines(exact.glsl));
}

// tp_22's exact equation (degree 8) is shorter GLSL than any approximation within 1e-2:
// the answer is exact, with both distances 0, and says why.
TEST(AnswerSdfRequest, ToleranceKeepsAShorterExactEquation) {
  const SdfAnswer answer = answer_sdf_request(decode_sdf_request(tp22_request(R"(, "tolerance": 0.01)")));
  ASSERT_TRUE(answer.approximation);
  const ApproximationSummary& a = *answer.approximation;
  EXPECT_NE(a.kept_exact.find("shorter"), std::string::npos) << a.kept_exact;
  EXPECT_EQ(answer.degree, 8);
  EXPECT_EQ(a.degree, 8);
  EXPECT_EQ(a.pieces, 1u);
  EXPECT_EQ(a.patch_to_surface, 0);
  EXPECT_EQ(a.glsl_lines, count_lines(answer.glsl));
  EXPECT_NE(encode_sdf_response(answer).find(R"("approximation":{"tolerance":0.01,"exact":true,"reason":)"),
            std::string::npos);
}

TEST(AnswerSdfRequest, ToleranceErrorsNameTheirField) {
  for (const char* bad : {"0", "-0.001", "0.6", "\"small\""}) {
    const InputError e = input_error_of(
        [&] { answer_sdf_request(decode_sdf_request(tp22_request(std::string(R"(, "tolerance": )") + bad))); });
    EXPECT_EQ(e.code(), "invalid_tolerance") << bad;
    EXPECT_EQ(e.field(), "tolerance") << bad;
  }
  const InputError implicit = input_error_of(
      [] { answer_sdf_request(decode_sdf_request(R"({"implicit": "x^2+y^2+z^2-1", "tolerance": 0.01})")); });
  EXPECT_EQ(implicit.code(), "invalid_tolerance");
  EXPECT_EQ(implicit.field(), "tolerance");
  const InputError scene = input_error_of([] {
    answer_sdf_request(decode_sdf_request(R"({"scene": {"type": "sphere", "radius": 1}, "tolerance": 0.01})"));
  });
  EXPECT_EQ(scene.code(), "invalid_tolerance");
  EXPECT_EQ(scene.field(), "tolerance");
  SdfRequest solid = decode_sdf_request(tp22_request(R"(, "tolerance": 0.01, "shape": "solid")"));
  EXPECT_EQ(input_error_of([&] { answer_sdf_request(solid); }).code(), "invalid_tolerance");
}

TEST(AnswerSdfRequest, SceneLeavesReportTheirApproximation) {
  const SdfRequest request = decode_sdf_request(R"({"scene": {"type": "union", "children": [
      {"type": "sphere", "radius": 0.5},
      {"type": "parametric", "x": "s-s^3/3+s*t^2", "y": "t-t^3/3+s^2*t", "z": "s^2-t^2", "domain": [[0, 1], [0, 1]],
       "tolerance": 0.05}]}})");
  const SdfAnswer answer = answer_sdf_request(request);
  ASSERT_EQ(answer.leaves.size(), 1u);
  ASSERT_TRUE(answer.leaves[0].approximation);
  EXPECT_TRUE(answer.leaves[0].trimmed);
  EXPECT_FALSE(answer.approximation);  // a scene's leaves say their own
  EXPECT_NE(encode_sdf_response(answer).find(R"("approximation":{"tolerance":0.05,"exact":false,)"), std::string::npos);
}

}  // namespace
}  // namespace implicitizer
