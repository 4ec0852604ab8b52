// Tests of server/codec/src/groebner_json.cpp: the decoder's fields and refusals,
// and the answer's JSON shape with and without elimination, by both methods.
#include "implicitizer/codec/groebner_json.hpp"

#include <gtest/gtest.h>
#include <rapidjson/document.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

TEST(DecodeGroebnerRequest, ReadsEveryField) {
  const GroebnerRequest r = decode_groebner_request(
      R"({"polynomials":["x-s","y-s^2"],"variables":["s","x","y"],"order":"lex","weights":[1,2,3],)"
      R"("eliminate":["s"],"timeout_ms":0})");
  EXPECT_EQ(r.polynomials, (std::vector<std::string>{"x-s", "y-s^2"}));
  EXPECT_EQ(*r.variables, (std::vector<std::string>{"s", "x", "y"}));
  EXPECT_EQ(r.order.name(), "lex");
  EXPECT_EQ(*r.weights, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(*r.eliminate, (std::vector<std::string>{"s"}));
  EXPECT_DOUBLE_EQ(*r.timeout_seconds, 0.0);
  EXPECT_EQ(r.proof, GroebnerProof::exact);  // the default
  EXPECT_EQ(decode_groebner_request(R"({"polynomials":["x"],"proof":"random_primes"})").proof,
            GroebnerProof::random_primes);
}

TEST(DecodeGroebnerRequest, RefusesBadFields) {
  EXPECT_EQ(input_error_of([] { decode_groebner_request("{}"); }).code(), "missing_field");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":"x"})"); }).field(), "polynomials");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":["x"],"weights":[1.5]})"); }).field(),
            "weights[0]");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":["x"],"ordering":"lex"})"); }).code(),
            "unknown_field");
  const InputError proof = input_error_of([] { decode_groebner_request(R"({"polynomials":["x"],"proof":"maybe"})"); });
  EXPECT_EQ(proof.code(), "unknown_proof");
  EXPECT_EQ(proof.field(), "proof");
  EXPECT_EQ(input_error_of([] { decode_groebner_request(R"({"polynomials":["x"],"proof":false})"); }).field(), "proof");
}

// The labelled unproven answer: the modular route's basis, "proven": false, and the
// random primes it was checked on. Buchberger's answer is exact whatever was asked.
TEST(AnswerGroebnerRequest, UnprovenIsLabelled) {
  GroebnerRequest r;
  r.polynomials = {"x^2+y", "y^2-x"};
  r.order = MonomialOrder::lex();
  r.proof = GroebnerProof::random_primes;
  r.method = GroebnerMethod::f4;
  const GroebnerAnswer a = answer_groebner_request(r);
  EXPECT_FALSE(a.route.proven());
  const std::string json = encode_groebner_response(a);
  EXPECT_EQ(json.rfind(R"({"basis":["y^4+y","x-y^2"],"order":"lex","method":"f4","proven":false,"stats":{)", 0), 0u)
      << json;
  ASSERT_TRUE(a.route.modular);
  EXPECT_EQ(a.route.modular->random_primes.size(), kUnprovenRandomChecks);
  EXPECT_NE(json.find(R"("random_primes":[")" + std::to_string(a.route.modular->random_primes.front()) + R"(",")"),
            std::string::npos)
      << json;
  r.method = GroebnerMethod::buchberger;
  EXPECT_TRUE(answer_groebner_request(r).route.proven());
}

TEST(AnswerGroebnerRequest, ReducedBasisAndElimination) {
  GroebnerRequest r;
  r.polynomials = {"x^2+y", "y^2-x"};
  r.order = MonomialOrder::lex();
  const GroebnerAnswer a = answer_groebner_request(r);
  const std::string json = encode_groebner_response(a);
  EXPECT_EQ(json.rfind(
                R"({"basis":["y^4+y","x-y^2"],"order":"lex","method":"buchberger","proven":true,"stats":{"pairs":)", 0),
            0u)
      << json;
  EXPECT_EQ(json.find("elimination_ideal"), std::string::npos);
  EXPECT_EQ(json.find(R"("modular":{)"), std::string::npos) << json;
  // The same basis modulo primes, proven, with the modular counters.
  GroebnerRequest m = r;
  m.method = GroebnerMethod::modular;
  const std::string modular = encode_groebner_response(answer_groebner_request(m));
  EXPECT_EQ(modular.rfind(
                R"({"basis":["y^4+y","x-y^2"],"order":"lex","method":"modular","proven":true,"stats":{"pairs":)", 0),
            0u)
      << modular;
  EXPECT_NE(modular.find(R"("modular":{"primes":)"), std::string::npos) << modular;
  EXPECT_NE(modular.find(R"("proven":true)"), std::string::npos) << modular;
  EXPECT_EQ(
      input_error_of([] { decode_groebner_request(R"({"polynomials":["x^2+y","y^2-x"],"method":"magic"})"); }).field(),
      "method");

  GroebnerRequest e;
  e.polynomials = {"x-s-t", "y-s*t", "z-s^2"};
  e.eliminate = std::vector<std::string>{"s", "t"};
  const GroebnerAnswer b = answer_groebner_request(e);
  ASSERT_TRUE(b.elimination_ideal.has_value());
  EXPECT_NE(encode_groebner_response(b).find(R"("elimination_ideal":["x^2*z-y^2-2*y*z-z^2"]})"), std::string::npos);
}

// A basis of over 5,000 terms is printed on two threads (json_writer.cpp): each
// polynomial in its place, as one thread prints it.
TEST(EncodeGroebnerResponse, ALargeBasisKeepsItsOrder) {
  const RingPtr ring = Ring::make({"x", "y", "z", "a", "b", "c"}, MonomialOrder::lex());
  GroebnerAnswer a;
  a.order = "lex";
  std::size_t terms = 0;
  for (const char* text : {"x-(a+b+c+1)^20", "y-(a+2*b+c+3)^20", "z-(2*a+b+3*c+1)^20", "a*b-c^2/7"}) {
    a.basis.push_back(parse_polynomial(text, ring));
    terms += a.basis.back().num_terms();
  }
  ASSERT_GE(terms, 5'000u);
  rapidjson::Document json;
  json.Parse(encode_groebner_response(a).c_str());
  ASSERT_TRUE(json.IsObject());
  const auto& basis = json["basis"].GetArray();
  ASSERT_EQ(basis.Size(), a.basis.size());
  for (rapidjson::SizeType i = 0; i < basis.Size(); ++i) EXPECT_EQ(basis[i].GetString(), to_string(a.basis[i]));
}

}  // namespace
}  // namespace implicitizer
