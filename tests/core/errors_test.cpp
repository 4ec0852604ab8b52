// Tests of the error types (lib/include/implicitizer/core/errors.hpp).

#include "implicitizer/core/errors.hpp"

#include <gtest/gtest.h>

namespace implicitizer {
namespace {

TEST(InputError, CarriesCodePositionAndField) {
  const InputError e("unexpected_token", "bad token", 7);
  EXPECT_EQ(e.code(), "unexpected_token");
  EXPECT_STREQ(e.what(), "bad token");
  EXPECT_EQ(e.position(), std::optional<std::size_t>(7));
  EXPECT_EQ(e.field(), "");
  const InputError named = e.in_field("polynomials[2]");
  EXPECT_EQ(named.field(), "polynomials[2]");
  EXPECT_EQ(named.code(), "unexpected_token");
  EXPECT_EQ(named.position(), std::optional<std::size_t>(7));
  EXPECT_EQ(e.field(), "");  // the original is unchanged
  EXPECT_FALSE(InputError("division_by_zero", "zero").position().has_value());
}

TEST(NoSingleEquation, KeepsTheGenerators) {
  const NoSingleEquation e("the image is a curve", {"x-y", "z"});
  EXPECT_EQ(e.generators(), (std::vector<std::string>{"x-y", "z"}));
  EXPECT_STREQ(e.what(), "the image is a curve");
}

}  // namespace
}  // namespace implicitizer
