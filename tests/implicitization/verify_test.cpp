// Tests of lib/src/implicitization/verify.cpp: the modular verification and the
// symbolic expansion agree, accept the true equations and reject corrupted ones.

#include "implicitizer/implicitization/verify.hpp"

#include <gtest/gtest.h>

#include "implicitization/surfaces.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"

namespace implicitizer {
namespace {

std::vector<testing::Surface> surfaces() {
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  auto all = testing::read_surfaces(dir + "surfaces_public.json");
  for (const auto& s : testing::read_surfaces(dir + "surfaces_hard.json")) {
    if (s.name == "tri_quadratic" || s.name == "tp_11_rational" || s.name == "tp_22" || s.name == "tri_cubic") {
      all.push_back(s);
    }
  }
  return all;
}

TEST(Verify, TrueEquationsPassBothChecks) {
  for (const auto& s : surfaces()) {
    SCOPED_TRACE(s.name);
    const Parametrization p = parse_parametrization(s.x, s.y, s.z);
    const Polynomial f = implicitize(p).implicit;
    EXPECT_TRUE(substitutes_to_zero(f, p));
    EXPECT_TRUE(substitutes_to_zero_symbolic(f, p));
  }
}

TEST(Verify, CorruptedEquationsAreRejectedByBoth) {
  // One coefficient off by one, a constant added, a multiple of another variable:
  // each candidate is wrong and both checks must say so.
  for (const auto& s : surfaces()) {
    SCOPED_TRACE(s.name);
    const Parametrization p = parse_parametrization(s.x, s.y, s.z);
    const Polynomial f = implicitize(p).implicit;
    const Polynomial one = Polynomial::constant(f.ring(), Rational(1));
    const Polynomial corrupted[] = {f + one, f + Polynomial::variable(f.ring(), 0) * one.scaled(Rational(1, 1000)),
                                    f * Polynomial::variable(f.ring(), 1) + one};
    for (const auto& g : corrupted) {
      EXPECT_FALSE(substitutes_to_zero(g, p));
      EXPECT_FALSE(substitutes_to_zero_symbolic(g, p));
    }
    // A multiple of the equation is not the equation, but it does vanish.
    EXPECT_TRUE(substitutes_to_zero(f * Polynomial::variable(f.ring(), 2), p));
  }
}

TEST(Verify, HugeAndTinyCoefficients) {
  // The plane x = 10^40 s, y = 10^-40 t, z = s + t: 10^-40 x + 10^40 y - z... scaled.
  const Parametrization p = parse_parametrization("10^40*s", "t/10^40", "s+t");
  const Polynomial f = parse_polynomial("x+10^80*y-10^40*z", space_ring());
  EXPECT_TRUE(substitutes_to_zero(f, p));
  EXPECT_FALSE(substitutes_to_zero(f + Polynomial::constant(f.ring(), Rational(1)), p));
  EXPECT_FALSE(substitutes_to_zero(parse_polynomial("x+10^80*y-(10^40+1)*z", space_ring()), p));
}

}  // namespace
}  // namespace implicitizer
