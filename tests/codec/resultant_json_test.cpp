// Tests of server/codec/src/resultant_json.cpp: the decoder's fields and refusals,
// and the answer's JSON shape.
#include "implicitizer/codec/resultant_json.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

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

}  // namespace
}  // namespace implicitizer
