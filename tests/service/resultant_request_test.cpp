// Tests of server/service/src/resultant_request.cpp: errors name their field, and
// the request's timeout stops the computation.
#include "implicitizer/service/resultant_request.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

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

}  // namespace
}  // namespace implicitizer
