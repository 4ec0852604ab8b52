// Tests of server/codec/src/sdf_json.cpp: the decoder's choices and refusals, and the
// answer's JSON for an implicit surface and for a scene.
#include "implicitizer/codec/sdf_json.hpp"

#include <gtest/gtest.h>

#include <string>

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
  EXPECT_NE(json.find(R"("leaves":[{"implicit":"x*y-z","degree":2,"trimmed":true}])"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("uniforms":[{"name":"ball_radius","type":"float","default":1.0}])"), std::string::npos)
      << json;
  // An implicit surface has no uniforms, and says so.
  EXPECT_NE(
      encode_sdf_response(answer_sdf_request(decode_sdf_request(R"({"implicit": "x"})"))).find(R"("uniforms":[])"),
      std::string::npos);
}

}  // namespace
}  // namespace implicitizer
