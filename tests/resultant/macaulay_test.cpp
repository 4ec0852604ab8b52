// Tests of lib/src/resultant/macaulay.cpp: the shape of Macaulay's matrix and of its
// extraneous minor, and det M / det E against implicit equations known otherwise.

#include "implicitizer/resultant/macaulay.hpp"

#include <gtest/gtest.h>

#include "implicitizer/polynomial/printer.hpp"
#include "resultant/resultant_support.hpp"

namespace implicitizer {
namespace {

using testing::auxiliary_system;
using testing::space_ring;
using testing::substituted;

Polynomial quotient(const MacaulayPencil& m, std::int32_t bound) {
  PencilDeterminantParams options;
  options.degree_bound = bound;
  options.divisor_minor = m.extraneous;
  options.stable_primes = 3;
  return pencil_determinant(m.matrix, space_ring(), options);
}

TEST(MacaulayPencil, SizesFollowTheDegree) {
  // d = 3n - 2; (d+1)(d+2)/2 monomials; the extraneous minor keeps those divisible by
  // two of r^n, s^n, t^n.
  const auto sys = auxiliary_system("1", "s^3+t", "t^3+s", "s*t^2");
  const MacaulayPencil m3 = macaulay_pencil(sys, 3);
  EXPECT_EQ(m3.matrix.size(), 36u);
  EXPECT_EQ(m3.extraneous.size(), 9u);
  const MacaulayPencil m1 = macaulay_pencil(auxiliary_system("1", "s", "t", "s+t"), 1);
  EXPECT_EQ(m1.matrix.size(), 3u);
  EXPECT_TRUE(m1.extraneous.empty());
}

TEST(MacaulayPencil, LinearPatchIsItsPlane) {
  EXPECT_EQ(to_string(quotient(macaulay_pencil(auxiliary_system("1", "s", "t", "1+s+2*t"), 1), 1).primitive_part()),
            "x+2*y-z+1");
}

TEST(MacaulayPencil, QuotientVanishesOnTriangularPatches) {
  // Total degree 2 (tri_quadratic of ../shared/bench), 3 rational, and 3: det M / det E
  // has degree n^2 and vanishes on the parametrization (checked by expanding).
  const std::array<Polynomial, 4> patches[] = {
      auxiliary_system("1", "-5+5*t^2+5*s+4*s*t-5*s^2", "4*t-3*t^2+3*s+5*s*t+3*s^2", "3-t+t^2-s+4*s*t+2*s^2"),
      auxiliary_system("7+s-t", "s^2+t", "t^2-s*t+1", "s+t+s*t"),
      auxiliary_system("1", "s^3-2*t^2+s*t+1", "t^3+s^2*t-s", "s^2*t-t^2*s+3*s+t^3"),
  };
  const std::int32_t degrees[] = {2, 2, 3};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::int32_t n = degrees[i];
    const Polynomial res = quotient(macaulay_pencil(patches[i], n), n * n);
    ASSERT_FALSE(res.is_zero()) << i;
    EXPECT_EQ(res.total_degree(), n * n) << i;
    EXPECT_TRUE(substituted(res, patches[i]).is_zero()) << i;
  }
}

TEST(MacaulayPencil, BasePointAtInfinityMakesTheQuotientVanish) {
  // The paraboloid x = s, y = t, z = s^2 + t^2: at infinity (r = 0) the forms share
  // the zeros of s^2 + t^2.
  const MacaulayPencil m = macaulay_pencil(auxiliary_system("1", "s", "t", "s^2+t^2"), 2);
  EXPECT_NE(probe_pencil_determinant(m.matrix, m.extraneous), PencilProbe::nonzero);
}

}  // namespace
}  // namespace implicitizer
