// Tests of server/codec: the JSON decoders' refusals, the encoders' shapes, and the
// request answerers the CLI and the server share.
#include "implicitizer/codec/json_codec.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/codec/groebner_request.hpp"
#include "implicitizer/codec/implicitize_request.hpp"
#include "implicitizer/codec/resultant_request.hpp"
#include "implicitizer/codec/sdf_request.hpp"
#include "codec/codec_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

TEST(DecodeImplicitizeRequest, ReadsEveryField) {
  const ImplicitizeRequest r = decode_implicitize_request(
      R"({"x":"s+t","y":"s","z":"t","parameters":["s","t"],"method":"groebner","timeout_ms":1500})");
  EXPECT_EQ(r.x, "s+t");
  EXPECT_EQ(r.y, "s");
  EXPECT_EQ(r.z, std::optional<std::string>("t"));
  ASSERT_TRUE(r.parameters.has_value());
  EXPECT_EQ(*r.parameters, (std::vector<std::string>{"s", "t"}));
  EXPECT_EQ(r.method, "groebner");
  ASSERT_TRUE(r.timeout_seconds.has_value());
  EXPECT_DOUBLE_EQ(*r.timeout_seconds, 1.5);
}

TEST(DecodeImplicitizeRequest, OptionalFieldsDefault) {
  const ImplicitizeRequest r = decode_implicitize_request(R"({"x":"s","y":"t","z":"s*t"})");
  EXPECT_FALSE(r.parameters.has_value());
  EXPECT_EQ(r.method, "auto");
  EXPECT_FALSE(r.timeout_seconds.has_value());
}

TEST(DecodeImplicitizeRequest, RefusesBadBodies) {
  EXPECT_EQ(input_error_of([] { decode_implicitize_request(""); }).code(), "invalid_json");
  const InputError syntax = input_error_of([] { decode_implicitize_request(R"({"x": "s",})"); });
  EXPECT_EQ(syntax.code(), "invalid_json");
  EXPECT_TRUE(syntax.position().has_value());
  EXPECT_EQ(input_error_of([] { decode_implicitize_request("[1]"); }).code(), "wrong_type");
  EXPECT_EQ(input_error_of([] { decode_implicitize_request("\"x\""); }).code(), "wrong_type");
  EXPECT_EQ(input_error_of([] { decode_implicitize_request("{\"x\":\"\xff\",\"y\":\"s\",\"z\":\"t\"}"); }).code(),
            "invalid_json");
}

TEST(DecodeImplicitizeRequest, NamesTheOffendingField) {
  const InputError missing = input_error_of([] { decode_implicitize_request(R"({"x":"s","z":"t"})"); });
  EXPECT_EQ(missing.code(), "missing_field");
  EXPECT_EQ(missing.field(), "y");
  // Without z the request is a plane curve.
  EXPECT_FALSE(decode_implicitize_request(R"({"x":"s","y":"t"})").z);
  const InputError type = input_error_of([] { decode_implicitize_request(R"({"x":1,"y":"t","z":"s"})"); });
  EXPECT_EQ(type.code(), "wrong_type");
  EXPECT_EQ(type.field(), "x");
  const InputError element =
      input_error_of([] { decode_implicitize_request(R"({"x":"s","y":"t","z":"s","parameters":["s",2]})"); });
  EXPECT_EQ(element.code(), "wrong_type");
  EXPECT_EQ(element.field(), "parameters[1]");
  const InputError unknown =
      input_error_of([] { decode_implicitize_request(R"({"x":"s","y":"t","z":"s","timeout":5})"); });
  EXPECT_EQ(unknown.code(), "unknown_field");
  EXPECT_EQ(unknown.field(), "timeout");
  const InputError twice = input_error_of([] { decode_implicitize_request(R"({"x":"s","x":"t","y":"t","z":"s"})"); });
  EXPECT_EQ(twice.code(), "duplicate_field");
  const InputError negative =
      input_error_of([] { decode_implicitize_request(R"({"x":"s","y":"t","z":"s","timeout_ms":-1})"); });
  EXPECT_EQ(negative.code(), "invalid_value");
  EXPECT_EQ(negative.field(), "timeout_ms");
}

TEST(DecodeImplicitizeRequest, RefusesDeepNestingWithoutRecursing) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(input_error_of([&] { decode_implicitize_request(deep); }).code(), "json_too_deep");
  // Brackets inside strings do not count.
  const std::string in_string = R"({"x":"[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[s","y":"t","z":"s"})";
  EXPECT_EQ(decode_implicitize_request(in_string).y, "t");
}

TEST(DecodeGroebnerRequest, ReadsEveryField) {
  const GroebnerRequest r = decode_groebner_request(
      R"({"polynomials":["x-s","y-s^2"],"variables":["s","x","y"],"order":"lex","weights":[1,2,3],)"
      R"("eliminate":["s"],"timeout_ms":0})");
  EXPECT_EQ(r.polynomials, (std::vector<std::string>{"x-s", "y-s^2"}));
  EXPECT_EQ(*r.variables, (std::vector<std::string>{"s", "x", "y"}));
  EXPECT_EQ(r.order, "lex");
  EXPECT_EQ(*r.weights, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(*r.eliminate, (std::vector<std::string>{"s"}));
  EXPECT_DOUBLE_EQ(*r.timeout_seconds, 0.0);
}

TEST(DecodeGroebnerRequest, RefusesBadFields) {
  EXPECT_EQ(input_error_of([] { decode_groebner_request("{}"); }).code(), "missing_field");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":"x"})"); }).field(), "polynomials");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":["x"],"weights":[1.5]})"); }).field(),
            "weights[0]");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":["x"],"ordering":"lex"})"); }).code(),
            "unknown_field");
}

TEST(AnswerGroebnerRequest, ReducedBasisAndElimination) {
  GroebnerRequest r;
  r.polynomials = {"x^2+y", "y^2-x"};
  r.order = "lex";
  const GroebnerAnswer a = answer_groebner_request(r);
  const std::string json = encode_groebner_response(a);
  EXPECT_EQ(json.rfind(R"({"basis":["y^4+y","x-y^2"],"order":"lex","method":"buchberger","stats":{"pairs":)", 0), 0u)
      << json;
  EXPECT_EQ(json.find("elimination_ideal"), std::string::npos);
  EXPECT_EQ(json.find(R"("modular":{)"), std::string::npos) << json;
  // The same basis modulo primes, proven, with the modular counters.
  GroebnerRequest m = r;
  m.method = "modular";
  const std::string modular = encode_groebner_response(answer_groebner_request(m));
  EXPECT_EQ(modular.rfind(R"({"basis":["y^4+y","x-y^2"],"order":"lex","method":"modular","stats":{"pairs":)", 0), 0u)
      << modular;
  EXPECT_NE(modular.find(R"("modular":{"primes":)"), std::string::npos) << modular;
  EXPECT_NE(modular.find(R"("proven":true)"), std::string::npos) << modular;
  m.method = "magic";
  EXPECT_EQ(input_error_of([&] { answer_groebner_request(m); }).field(), "method");

  GroebnerRequest e;
  e.polynomials = {"x-s-t", "y-s*t", "z-s^2"};
  e.eliminate = std::vector<std::string>{"s", "t"};
  const GroebnerAnswer b = answer_groebner_request(e);
  ASSERT_TRUE(b.elimination_ideal.has_value());
  EXPECT_NE(encode_groebner_response(b).find(R"("elimination_ideal":["x^2*z-y^2-2*y*z-z^2"]})"), std::string::npos);
}

TEST(AnswerGroebnerRequest, ErrorsNameTheirField) {
  GroebnerRequest r;
  r.polynomials = {"x+y", "x+$"};
  const InputError parse = input_error_of([&] { answer_groebner_request(r); });
  EXPECT_EQ(parse.field(), "polynomials[1]");
  EXPECT_EQ(parse.position(), 2u);
  r.polynomials = {"x+y"};
  r.eliminate = std::vector<std::string>{"w"};
  EXPECT_EQ(input_error_of([&] { answer_groebner_request(r); }).field(), "eliminate[0]");
  r.eliminate = std::vector<std::string>{"x", "y"};
  EXPECT_EQ(input_error_of([&] { answer_groebner_request(r); }).code(), "invalid_variables");
  r.eliminate.reset();
  r.polynomials.clear();
  EXPECT_EQ(input_error_of([&] { answer_groebner_request(r); }).code(), "empty_input");
}

TEST(DecodeResultantRequest, ReadsEveryField) {
  const ResultantRequest r =
      decode_resultant_request(R"({"polynomials":["t^2+x","y*t+1"],"variable":"t","timeout_ms":250})");
  EXPECT_EQ(r.polynomials, (std::vector<std::string>{"t^2+x", "y*t+1"}));
  EXPECT_EQ(r.variable, "t");
  ASSERT_TRUE(r.timeout_seconds.has_value());
  EXPECT_DOUBLE_EQ(*r.timeout_seconds, 0.25);
  EXPECT_FALSE(decode_resultant_request(R"({"polynomials":["t","x"],"variable":"t"})").timeout_seconds.has_value());
}

TEST(DecodeResultantRequest, RefusesBadFields) {
  const InputError count = input_error_of([] { decode_resultant_request(R"({"polynomials":["t"],"variable":"t"})"); });
  EXPECT_EQ(count.code(), "wrong_number_of_polynomials");
  EXPECT_EQ(count.field(), "polynomials");
  EXPECT_EQ(input_error_of([] { decode_resultant_request(R"({"polynomials":["t","x","y"],"variable":"t"})"); }).code(),
            "wrong_number_of_polynomials");
  const InputError missing = input_error_of([] { decode_resultant_request(R"({"polynomials":["t","x"]})"); });
  EXPECT_EQ(missing.code(), "missing_field");
  EXPECT_EQ(missing.field(), "variable");
  EXPECT_EQ(input_error_of([] { decode_resultant_request(R"({"variable":"t"})"); }).field(), "polynomials");
  EXPECT_EQ(input_error_of([] { decode_resultant_request(R"({"polynomials":["t",1],"variable":"t"})"); }).field(),
            "polynomials[1]");
  EXPECT_EQ(input_error_of([] { decode_resultant_request(R"({"polynomials":["t","x"],"variable":["t"]})"); }).code(),
            "wrong_type");
  const InputError unknown =
      input_error_of([] { decode_resultant_request(R"({"polynomials":["t","x"],"variable":"t","var":"t"})"); });
  EXPECT_EQ(unknown.code(), "unknown_field");
  EXPECT_NE(std::string(unknown.what()).find("(allowed: polynomials, variable, timeout_ms)"), std::string::npos);
  EXPECT_EQ(input_error_of([] { decode_resultant_request(R"({"polynomials":["t","x"],"variable":"t",)"); }).code(),
            "invalid_json");
}

TEST(AnswerResultantRequest, EncodesTheContractShape) {
  ResultantRequest r;
  r.polynomials = {"t^2+x", "y*t+1"};
  r.variable = "t";
  const std::string json = encode_resultant_response(answer_resultant_request(r));
  EXPECT_EQ(json.rfind(R"({"resultant":"x*y^2+1","variables":["x","y"],"degree":3,"method":"subresultant",)"
                       R"("elapsed_ms":)",
                       0),
            0u)
      << json;
  // Variables in order of first appearance; rational coefficients stay exact.
  r.polynomials = {"3/2*b*t+1/3", "t^2-a/5"};
  const ResultantAnswer a = answer_resultant_request(r);
  EXPECT_EQ(a.variables, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(to_string(a.resultant), "-9/20*b^2*a+1/9");  // Res(αt + β, t^2 − γ) = β^2 − α^2·γ
  // A zero resultant has degree -1.
  r.polynomials = {"t-x", "t^2-x^2"};
  const ResultantAnswer zero = answer_resultant_request(r);
  EXPECT_TRUE(zero.resultant.is_zero());
  EXPECT_EQ(zero.degree, -1);
  EXPECT_NE(encode_resultant_response(zero).find(R"("resultant":"0","variables":["x"],"degree":-1,)"),
            std::string::npos);
}

TEST(AnswerResultantRequest, ErrorsNameTheirField) {
  ResultantRequest r;
  r.polynomials = {"t+x", "t+$"};
  r.variable = "t";
  const InputError parse = input_error_of([&] { answer_resultant_request(r); });
  EXPECT_EQ(parse.code(), "unexpected_character");
  EXPECT_EQ(parse.field(), "polynomials[1]");
  EXPECT_EQ(parse.position(), 2u);
  r.polynomials = {"t+x", "1/t"};
  const InputError denominator = input_error_of([&] { answer_resultant_request(r); });
  EXPECT_EQ(denominator.code(), "non_constant_denominator");
  EXPECT_EQ(denominator.field(), "polynomials[1]");
  r.polynomials = {"t+x", "t-x"};
  r.variable = "s";
  const InputError unknown = input_error_of([&] { answer_resultant_request(r); });
  EXPECT_EQ(unknown.code(), "unknown_variable");
  EXPECT_EQ(unknown.field(), "variable");
  r.variable = "2t";
  EXPECT_EQ(input_error_of([&] { answer_resultant_request(r); }).code(), "invalid_variables");
  r.variable = "t";
  r.polynomials = {"t"};
  EXPECT_EQ(input_error_of([&] { answer_resultant_request(r); }).code(), "wrong_number_of_polynomials");
}

TEST(AnswerResultantRequest, TimeoutStopsIt) {
  ResultantRequest r;
  r.polynomials = {"(x+y+z+1)^6*t^12+(x-y)^5*t^7+x*y*z*t+1", "(x-2*y+z)^6*t^11+(y+z)^4*t^5+x*t^2+7"};
  r.variable = "t";
  r.timeout_seconds = 1e-3;
  try {
    answer_resultant_request(r);
    ADD_FAILURE() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
}

TEST(AnswerImplicitizeRequest, EncodesTheContractShape) {
  ImplicitizeRequest r;
  r.x = "s+t";
  r.y = "s";
  r.z = "t";
  const std::string json = encode_implicitize_response(answer_implicitize_request(r));
  // The plane: degree ≤ 4, so interpolation answers first (docs/algorithms.md), and
  // the stats say so.
  EXPECT_EQ(json.rfind(R"({"implicit":"x-y-z","degree":1,"variables":["x","y","z"],"method":"interpolation",)"
                       R"("verified":true,"elapsed_ms":)",
                       0),
            0u)
      << json;
  EXPECT_NE(json.find(R"("route":"interpolation: the degree is at most 4, tried first")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("reproduce":{"singular":")"), std::string::npos);
  // By the resultant: its 3x3 Macaulay matrix, with the probe's flags.
  r.method = "resultant";
  const std::string resultant = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_NE(resultant.find(R"("resultant":{"dixon_vanishes":true,"macaulay_vanishes":false,"formulation":"macaulay",)"
                           R"("matrix_size":3,"extraneous_size":0,"degree_bound":1,"map_degree":1,"primes":)"),
            std::string::npos)
      << resultant;
  r.method = "groebner";
  const std::string groebner = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_NE(groebner.find(R"("method":"groebner")"), std::string::npos);
  EXPECT_EQ(groebner.find(R"("resultant":{)"), std::string::npos) << "Gröbner was forced: no probe";
  r.method = "interpolation";
  const std::string interpolation = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_NE(interpolation.find(R"("method":"interpolation","verified":true)"), std::string::npos) << interpolation;
  EXPECT_NE(interpolation.find(R"("interpolation":{"degree_bound":1,"degree":1,"rows":12,"columns":4,"primes":)"),
            std::string::npos)
      << interpolation;
  EXPECT_EQ(interpolation.find(R"("resultant":{)"), std::string::npos) << interpolation;
  r.method = "magic";
  const InputError method = input_error_of([&] { answer_implicitize_request(r); });
  EXPECT_EQ(method.code(), "unknown_method");
  EXPECT_EQ(method.field(), "method");
}

TEST(AnswerImplicitizeRequest, PlaneCurveWithoutZ) {
  // The folium-like cubic x = t/(1+t^3)... here the nodal cubic x = t^2 - 1,
  // y = t^3 - t: y^2 = x^2 (x + 1), by the Sylvester resultant.
  ImplicitizeRequest r;
  r.x = "t^2-1";
  r.y = "t^3-t";
  const std::string json = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_EQ(json.rfind(R"({"implicit":"x^3+x^2-y^2","degree":3,"variables":["x","y"],"method":"resultant",)", 0), 0u)
      << json;
  EXPECT_NE(json.find(R"("formulation":"sylvester")"), std::string::npos) << json;
}

TEST(AnswerSdfRequest, ModeSafeAnswersTheBound) {
  const SdfRequest request = decode_sdf_request(R"({"implicit": "x^2+y^2+z^2-1", "mode": "safe", "name": "ball"})");
  EXPECT_EQ(request.mode, "safe");
  const SdfAnswer answer = answer_sdf_request(request);
  EXPECT_EQ(answer.mode, "safe");
  EXPECT_EQ(answer.function, "ball_sdf");
  EXPECT_NE(answer.glsl.find("float ball_sdf(vec3 p)"), std::string::npos);
  EXPECT_NE(answer.glsl.find("safe distance bound"), std::string::npos);
  EXPECT_EQ(answer.glsl.find("pow"), std::string::npos);
  EXPECT_NE(encode_sdf_response(answer).find(R"("mode":"safe")"), std::string::npos);
  // Fast stays the default.
  EXPECT_EQ(answer_sdf_request(decode_sdf_request(R"({"implicit": "x"})")).mode, "fast");
}

TEST(AnswerSdfRequest, ErrorsNameTheirField) {
  SdfRequest r;
  r.implicit = "x^60+y";
  r.mode = "safe";
  const InputError degree = input_error_of([&] { answer_sdf_request(r); });
  EXPECT_EQ(degree.code(), "degree_too_high");
  EXPECT_EQ(degree.field(), "implicit");
  r.mode = "exact";
  const InputError mode = input_error_of([&] { answer_sdf_request(r); });
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
  EXPECT_NE(encode_sdf_response(answer_sdf_request(decode_sdf_request(R"({"implicit": "x"})"))).find(R"("uniforms":[])"),
            std::string::npos);
}

TEST(EncodeError, Shapes) {
  EXPECT_EQ(encode_error(InputError("unexpected_character", "bad \"$\"", 3).in_field("y")),
            R"({"error":{"code":"unexpected_character","message":"bad \"$\"","position":3,"field":"y"}})");
  EXPECT_EQ(encode_error(InputError("missing_field", "no")), R"({"error":{"code":"missing_field","message":"no"}})");
  EXPECT_EQ(encode_error(NoSingleEquation("curve", {"x^2-y", "y^2-x*z"})),
            R"({"error":{"code":"no_single_equation","message":"curve","generators":["x^2-y","y^2-x*z"]}})");
  EXPECT_EQ(encode_error(LimitExceeded(Limit::time, "slow")),
            R"({"error":{"code":"time_limit_exceeded","message":"slow","limit":"time"}})");
  EXPECT_EQ(encode_error("not_found", "no such path"), R"({"error":{"code":"not_found","message":"no such path"}})");
}

TEST(EncodeServerLines, HealthAndAccessLog) {
  EXPECT_EQ(encode_health_status("ok"), R"({"status":"ok"})");
  EXPECT_EQ(encode_access_log_entry("POST", "/v1/implicitize", 200, 3.25, 924),
            R"({"method":"POST","path":"/v1/implicitize","status":200,"ms":3.25,"bytes":924})");
  EXPECT_EQ(encode_access_log_entry("GET", "/a\"b", 404, 0, 0),
            R"({"method":"GET","path":"/a\"b","status":404,"ms":0.0,"bytes":0})");
}

}  // namespace
}  // namespace implicitizer
