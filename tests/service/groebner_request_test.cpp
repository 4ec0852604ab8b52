// Tests of server/service/src/groebner_request.cpp: errors name their field.
#include "implicitizer/service/groebner_request.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

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

}  // namespace
}  // namespace implicitizer
