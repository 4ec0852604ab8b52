// Tests of lib/src/resultant/auxiliary_resultant.cpp: which formulation is chosen,
// base points (Theorem 1.14) detected as an identically zero resultant, and the
// budget.

#include "implicitizer/resultant/auxiliary_resultant.hpp"

#include <gtest/gtest.h>

#include "resultant/resultant_support.hpp"

namespace implicitizer {
namespace {

using testing::auxiliary_system;
using testing::space_ring;
using testing::substituted;

TEST(AuxiliaryResultant, TensorProductPatchUsesDixon) {
  // tp_22 of ../shared/bench: bidegree (2,2), implicit degree 8 < 4^2 = 16.
  const auto sys = auxiliary_system("1", "3-t-2*t^2-3*s-5*s*t+5*s^2-s^2*t+4*s^2*t^2",
                                    "-3+5*t-t^2-s+5*s*t-4*s*t^2+2*s^2+5*s^2*t",
                                    "-3-3*t-4*t^2-2*s+5*s*t-3*s*t^2+3*s^2+5*s^2*t+2*s^2*t^2");
  const AuxiliaryResultant aux = auxiliary_resultant(sys, space_ring());
  EXPECT_EQ(aux.stats.formulation, AuxiliaryFormulation::dixon);
  EXPECT_EQ(aux.stats.matrix_size, 8u);
  EXPECT_EQ(aux.stats.degree_bound, 8);
  EXPECT_TRUE(aux.stats.determinant.proven);
  EXPECT_EQ(aux.resultant.total_degree(), 8);
  EXPECT_TRUE(substituted(aux.resultant, sys).is_zero());
}

TEST(AuxiliaryResultant, TriangularPatchUsesMacaulay) {
  // Total degree 2: Macaulay's bound 4 is below Dixon's 2·2·2 = 8.
  const auto sys = auxiliary_system("1", "-5+5*t^2+5*s+4*s*t-5*s^2", "4*t-3*t^2+3*s+5*s*t+3*s^2",
                                    "3-t+t^2-s+4*s*t+2*s^2");
  const AuxiliaryResultant aux = auxiliary_resultant(sys, space_ring());
  EXPECT_EQ(aux.stats.formulation, AuxiliaryFormulation::macaulay);
  EXPECT_EQ(aux.stats.matrix_size, 15u);
  EXPECT_EQ(aux.stats.extraneous_size, 3u);
  EXPECT_EQ(aux.resultant.total_degree(), 4);
  EXPECT_TRUE(substituted(aux.resultant, sys).is_zero());
}

TEST(AuxiliaryResultant, ImproperParametrizationGivesAPower) {
  // x = s^2, y = t^2, z = s^2 + t^2 + s^2 t^2 covers its surface four times: the
  // resultant is c·f^4 for the quadric f = z - x - y - xy... as a (2,2) patch.
  const auto sys = auxiliary_system("1", "s^2", "t^2", "s^2+t^2+s^2*t^2");
  const AuxiliaryResultant aux = auxiliary_resultant(sys, space_ring());
  ASSERT_FALSE(aux.resultant.is_zero());
  EXPECT_EQ(aux.resultant.total_degree(), 8);
  const Polynomial f = parse_polynomial("z-x-y-x*y", space_ring());
  EXPECT_EQ(aux.resultant.primitive_part(), f.pow(4).primitive_part());
}

TEST(AuxiliaryResultant, BasePointsMakeBothFormulationsVanish) {
  // The stereographic sphere, Whitney's umbrella (x = st, y = t, z = s^2) and the
  // rational torus torus_R2_r1 of ../shared/bench over its common denominator.
  const std::array<Polynomial, 4> cases[] = {
      auxiliary_system("1+s^2+t^2", "2*s", "2*t", "s^2+t^2-1"),
      auxiliary_system("1", "s*t", "t", "s^2"),
      auxiliary_system("(1+s^2)*(1+t^2)", "(3+t^2)*(1-s^2)", "(3+t^2)*2*s", "2*t*(1+s^2)"),
  };
  for (const auto& sys : cases) {
    const AuxiliaryResultant aux = auxiliary_resultant(sys, space_ring());
    EXPECT_TRUE(aux.resultant.is_zero());
    EXPECT_TRUE(aux.stats.dixon_vanishes);
    EXPECT_TRUE(aux.stats.macaulay_vanishes);
  }
}

TEST(AuxiliaryResultant, BasePointsDependOnTheCompactification) {
  // x = st, y = s, z = t: homogenized in (r, s, t) the forms r^2, st, rs, rt share
  // (0:1:0) and (0:0:1), so Macaulay's quotient on P² vanishes (Theorem 1.14 as the
  // seed states it); as a bidegree-(1,1) patch on P1xP1 there is no common zero and
  // Dixon's 2x2 determinant is the implicit equation.
  const auto sys = auxiliary_system("1", "s*t", "s", "t");
  const AuxiliaryResultant aux = auxiliary_resultant(sys, space_ring());
  EXPECT_TRUE(aux.stats.macaulay_vanishes);
  EXPECT_FALSE(aux.stats.dixon_vanishes);
  EXPECT_EQ(aux.stats.formulation, AuxiliaryFormulation::dixon);
  EXPECT_EQ(aux.resultant.primitive_part(), parse_polynomial("x-y*z", space_ring()).primitive_part());
}

TEST(AuxiliaryResultant, ImagesThatAreNotSurfacesVanish) {
  EXPECT_TRUE(auxiliary_resultant(auxiliary_system("1", "s+t", "s+t", "(s+t)^2"), space_ring()).resultant.is_zero());
  EXPECT_TRUE(auxiliary_resultant(auxiliary_system("1", "s", "s^2", "s^3"), space_ring()).resultant.is_zero());
}

TEST(AuxiliaryResultant, BudgetStopsIt) {
  // tp_33 under a 1 ms deadline.
  const auto sys = auxiliary_system(
      "1", "3+2*t^2+t^3-3*s-5*s*t+s^2-2*s^2*t-3*s^2*t^2-3*s^2*t^3+4*s^3-3*s^3*t+3*s^3*t^2-s^3*t^3",
      "3+t-2*t^2-4*t^3-3*s+s*t+5*s*t^2+2*s*t^3+4*s^2-s^2*t-5*s^2*t^2+s^2*t^3-5*s^3-3*s^3*t-5*s^3*t^2+3*s^3*t^3",
      "-2-2*t-4*t^2-5*t^3+3*s-3*s*t-4*s*t^2-4*s*t^3-s^2+3*s^2*t-3*s^2*t^2-2*s^2*t^3+3*s^3+5*s^3*t-2*s^3*t^2+2*s^3*t^3");
  AuxiliaryResultantParams options;
  options.budget = Budget::with_timeout(0.001);
  try {
    auxiliary_resultant(sys, space_ring(), options);
    FAIL() << "tp_33 finished in 1 ms";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
}

}  // namespace
}  // namespace implicitizer
