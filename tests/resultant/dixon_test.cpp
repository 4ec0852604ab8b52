// Tests of lib/src/resultant/dixon.cpp: the Dixon matrix of the auxiliary system
// has the documented shape, and its determinant is a constant times the implicit
// equation that the Gröbner route (independent code) finds.

#include "implicitizer/resultant/dixon.hpp"

#include <gtest/gtest.h>

#include "implicitizer/polynomial/printer.hpp"
#include "resultant/resultant_support.hpp"

namespace implicitizer {
namespace {

using testing::auxiliary_system;
using testing::space_ring;
using testing::substituted;

Polynomial determinant(const MatrixPencil& m, std::int32_t bound) {
  PencilDeterminantParams options;
  options.degree_bound = bound;
  options.proven_bits = m.determinant_coefficient_bits();
  return pencil_determinant(m, space_ring(), options);
}

TEST(DixonPencil, BilinearPatchIsTheHyperbolicParaboloid) {
  // x = s, y = t, z = st has no base points on P1xP1: a 2x2 Dixon matrix whose
  // determinant is a multiple of z - xy.
  const MatrixPencil m = dixon_pencil(auxiliary_system("1", "s", "t", "s*t"), 1, 1);
  EXPECT_EQ(m.size(), 2u);
  EXPECT_EQ(to_string(determinant(m, 2).primitive_part()), "x*y-z");
}

TEST(DixonPencil, SizeIs2mnWithThreeVariables) {
  const auto sys = auxiliary_system("1", "s^2*t+s*t^2+1", "s^2-t^3+s*t", "s^2*t^3+s+2*t");
  const MatrixPencil m = dixon_pencil(sys, 2, 3);
  EXPECT_EQ(m.size(), 12u);
  EXPECT_EQ(m.num_variables(), 3u);
}

TEST(DixonPencil, DeterminantsVanishOnRationalAndHigherDegreePatches) {
  // Rational bidegree (1,1), polynomial (2,1) and (2,2): det has degree 2mn and
  // vanishes on the parametrization (checked by expanding, not modularly).
  const std::array<Polynomial, 4> patches[] = {
      auxiliary_system("3+s+t+s*t", "s", "t+2*s", "s*t-1"),
      auxiliary_system("1", "s^2*t+s-t", "s^2+3*s*t-t", "s*t+t+5*s^2"),
      auxiliary_system("1", "3-t-2*t^2-3*s-5*s*t+5*s^2-s^2*t+4*s^2*t^2", "-3+5*t-t^2-s+5*s*t-4*s*t^2+2*s^2+5*s^2*t",
                       "-3-3*t-4*t^2-2*s+5*s*t-3*s*t^2+3*s^2+5*s^2*t+2*s^2*t^2"),
  };
  const std::int32_t bidegrees[][2] = {{1, 1}, {2, 1}, {2, 2}};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto [m, n] = bidegrees[i];
    const Polynomial det = determinant(dixon_pencil(patches[i], m, n), 2 * m * n);
    ASSERT_FALSE(det.is_zero()) << i;
    EXPECT_EQ(det.total_degree(), 2 * m * n) << i;
    EXPECT_TRUE(substituted(det, patches[i]).is_zero()) << i;
  }
}

TEST(DixonPencil, BasePointsMakeTheDeterminantVanish) {
  // x = s, y = t, z = s^2 + t^2 as a bidegree-(2,2) patch: the missing s^2 t^2 term
  // leaves base points at infinity on P1xP1.
  const MatrixPencil m = dixon_pencil(auxiliary_system("1", "s", "t", "s^2+t^2"), 2, 2);
  EXPECT_EQ(probe_pencil_determinant(m, {}), PencilProbe::zero);
  EXPECT_TRUE(determinant(m, 8).is_zero());
}

TEST(DixonPencil, RefusesWhatDoesNotFit) {
  EXPECT_THROW(dixon_pencil(auxiliary_system("1", "s^2", "t", "s"), 1, 1), std::invalid_argument);
  EXPECT_THROW(dixon_pencil(auxiliary_system("1", "s", "t", "s"), 0, 1), std::invalid_argument);
  EXPECT_THROW(dixon_pencil(auxiliary_system("1", "s/2", "t", "s"), 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace implicitizer
