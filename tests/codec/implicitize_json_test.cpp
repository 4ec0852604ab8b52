// Tests of server/codec/src/implicitize_json.cpp: the decoder's fields and refusals,
// and the answer's JSON shape on every route.
#include "implicitizer/codec/implicitize_json.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

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
  EXPECT_EQ(r.method, ImplicitizationMethod::groebner);
  ASSERT_TRUE(r.timeout_seconds.has_value());
  EXPECT_DOUBLE_EQ(*r.timeout_seconds, 1.5);
}

TEST(DecodeImplicitizeRequest, OptionalFieldsDefault) {
  const ImplicitizeRequest r = decode_implicitize_request(R"({"x":"s","y":"t","z":"s*t"})");
  EXPECT_FALSE(r.parameters.has_value());
  EXPECT_EQ(r.method, ImplicitizationMethod::automatic);
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
  r.method = ImplicitizationMethod::resultant;
  const std::string resultant = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_NE(resultant.find(R"("resultant":{"dixon_vanishes":true,"macaulay_vanishes":false,"formulation":"macaulay",)"
                           R"("matrix_size":3,"extraneous_size":0,"degree_bound":1,"map_degree":1,"primes":)"),
            std::string::npos)
      << resultant;
  r.method = ImplicitizationMethod::groebner;
  const std::string groebner = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_NE(groebner.find(R"("method":"groebner")"), std::string::npos);
  EXPECT_EQ(groebner.find(R"("resultant":{)"), std::string::npos) << "Gröbner was forced: no probe";
  r.method = ImplicitizationMethod::interpolation;
  const std::string interpolation = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_NE(interpolation.find(R"("method":"interpolation","verified":true)"), std::string::npos) << interpolation;
  EXPECT_NE(interpolation.find(R"("interpolation":{"degree_bound":1,"degree":1,"rows":12,"columns":4,"primes":)"),
            std::string::npos)
      << interpolation;
  EXPECT_EQ(interpolation.find(R"("resultant":{)"), std::string::npos) << interpolation;
  const InputError method =
      input_error_of([] { decode_implicitize_request(R"({"x":"s+t","y":"s","z":"t","method":"magic"})"); });
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

// Issue 20: the substitution and the rational form, between stats and reproduce, only
// for an input with functions.
TEST(AnswerImplicitizeRequest, SaysHowFunctionsWereMadeRational) {
  ImplicitizeRequest r;
  r.x = "cos(2*t)";
  r.y = "sin(t)";
  const std::string json = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_EQ(json.rfind(R"({"implicit":"2*y^2+x-1","degree":2,)", 0), 0u) << json;
  EXPECT_NE(json.find(R"j("substitution":[{"parameter":"t","variable":"tt","kind":"half_angle",)j"
                      R"j("formula":"tt = tan(t/2)"}],"rational_parametrization":{"parameters":["tt"],)j"
                      R"j("x":"(tt^4-6*tt^2+1)/(tt^4+2*tt^2+1)","y":"2*tt/(tt^2+1)"},"reproduce":{)j"),
            std::string::npos)
      << json;
  r.x = "1-2*s^2";
  r.y = "s";
  const std::string rational = encode_implicitize_response(answer_implicitize_request(r));
  EXPECT_EQ(rational.find("substitution"), std::string::npos) << rational;
  EXPECT_EQ(rational.find("rational_parametrization"), std::string::npos) << rational;
}

}  // namespace
}  // namespace implicitizer
