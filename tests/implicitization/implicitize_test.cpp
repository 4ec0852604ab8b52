#include "implicitizer/implicitization/implicitize.hpp"

#include <gtest/gtest.h>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitization/surfaces.hpp"

namespace implicitizer {
namespace {

std::string implicit_of(const std::string& x, const std::string& y, const std::string& z) {
  return to_string(implicitize(parse_parametrization(x, y, z)).implicit);
}

// Equal up to a non-zero rational factor: both primitive with positive leading
// coefficient, so they must be equal.
void expect_same_surface(const std::string& ours, const std::string& theirs) {
  const Polynomial a = parse_polynomial(ours, space_ring()).primitive_part();
  const Polynomial b = parse_polynomial(theirs, space_ring()).primitive_part();
  EXPECT_EQ(to_string(a), to_string(b));
}

TEST(Implicitize, PublicSurfacesMatchSingular) {
  const auto surfaces = testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json");
  ASSERT_GE(surfaces.size(), 12u);
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    const ImplicitizeResult r = implicitize(parse_parametrization(s.x, s.y, s.z));
    EXPECT_TRUE(r.verified);
    EXPECT_EQ(r.degree, s.degree);
    expect_same_surface(to_string(r.implicit),
                        testing::read_text(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/expected/" + s.name + ".txt"));
  }
}

TEST(Implicitize, SeedExample13IsThePlane) {
  // Example 1.3 of the seed thesis: -x+y+z = 0, printed primitive with positive lc.
  EXPECT_EQ(implicit_of("s+t", "s", "t"), "x-y-z");
}

TEST(Implicitize, SeedTable42WithItsSlipsCorrected) {
  EXPECT_EQ(implicit_of("t^2+s^2", "t", "s"), "y^2+z^2-x");           // elliptic paraboloid
  EXPECT_EQ(implicit_of("t", "s", "t^2-s^2"), "x^2-y^2-z");           // hyperbolic paraboloid
  EXPECT_EQ(implicit_of("s", "t", "s^2+t^2"), "x^2+y^2-z");           // the "ellipsoid" is a paraboloid
  EXPECT_EQ(implicit_of("(t-s)/t", "s/t", "(s^3+t^2)/t^2"), "x+y-1");  // Sage 1
  EXPECT_EQ(implicit_of("s/t", "s/t^2", "(s+t)/s"), "x*z-x-1");       // Sage 2
  EXPECT_EQ(implicit_of("s/(s*t)", "(t^2-s)/t^2", "t/s"), "y*z+x-z");  // Sage 3 (x = s/(s t))
  EXPECT_EQ(implicit_of("(t-s^2)/(s*t)", "s^2/3", "s"), "z^2-3*y");   // Sage 4
}

TEST(Implicitize, CurvesAndPointsHaveNoSingleEquation) {
  EXPECT_THROW(implicitize(parse_parametrization("t", "t^2", "t^3")), NoSingleEquation);
  EXPECT_THROW(implicitize(parse_parametrization("1", "2", "3")), NoSingleEquation);
  try {
    implicitize(parse_parametrization("t", "t^2", "t^3"));
  } catch (const NoSingleEquation& e) {
    // The twisted cubic: its ideal has the three-element grevlex basis
    // x^2 - y, x*y - z, y^2 - x*z (CLO §1.3); every one is listed.
    ASSERT_EQ(e.generators().size(), 3u);
    EXPECT_EQ(e.generators()[0], "y^2-x*z");
    EXPECT_EQ(e.generators()[1], "x*y-z");
    EXPECT_EQ(e.generators()[2], "x^2-y");
  }
}

TEST(Implicitize, ThreeParametersFillSpace) {
  EXPECT_THROW(implicitize(parse_parametrization("s", "t", "u")), NoSingleEquation);
}

TEST(Implicitize, BadInput) {
  EXPECT_THROW(parse_parametrization("x*s", "t", "s"), InputError);
  try {
    parse_parametrization("s+t", "s", "1/(s-s)");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "division_by_zero");
    EXPECT_EQ(e.field(), "z");
    EXPECT_EQ(e.position(), 1u);
  }
  try {
    parse_parametrization("s+t", "s", "u", std::vector<std::string>{"s", "t"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "unknown_variable");
    EXPECT_EQ(e.field(), "z");
  }
}

TEST(Implicitize, BudgetExpires) {
  const auto hard = testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json");
  for (const auto& s : hard) {
    if (s.name != "tp_22") continue;
    ImplicitizeOptions options;
    options.groebner.budget.set_timeout(0.05);
    try {
      implicitize(parse_parametrization(s.x, s.y, s.z), options);
      FAIL() << "tp_22 finished in 50 ms";
    } catch (const LimitExceeded& e) {
      EXPECT_EQ(e.limit(), Limit::time);
    }
  }
}

}  // namespace
}  // namespace implicitizer
