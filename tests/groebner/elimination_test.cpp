/// Tests of lib/src/groebner/elimination.cpp: elimination ideals through an
/// elimination order (CLO Thm 3.1.2). Known implicitizations give exact answers;
/// the property tests check what the theorem promises on random ideals: the result
/// lies in the remaining variables, lies in the ideal, is a reduced basis of the
/// elimination ideal for the requested order, and does not depend on which
/// elimination order computed it (the weighted one used for grevlex or the block one).

#include "implicitizer/groebner/elimination.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/groebner/division.hpp"
#include "implicitizer/groebner/reduced_basis.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using testing::parse_all;
using testing::print_all;

constexpr int kNumRandomIdeals = 20;

using Strings = std::vector<std::string>;

// Eliminates `names` from `generators` (parsed over `variables`, in grevlex).
EliminationResult eliminate_from(const Strings& generators, const std::vector<std::string>& variables,
                                 const std::vector<std::string>& names,
                                 const MonomialOrder& remaining = MonomialOrder::grevlex()) {
  const RingPtr ring = Ring::make(variables);
  return eliminate(parse_all(generators, ring), names, BuchbergerParams(), remaining);
}

// The cuspidal cubic (t^2, t^3): x^3 - y^2, monic for the leading monomial x^3,
// wherever t sits among the variables and for every remaining order.
TEST(EliminationTest, CuspidalCubic) {
  for (const auto& variables : {std::vector<std::string>{"t", "x", "y"}, std::vector<std::string>{"x", "y", "t"},
                                std::vector<std::string>{"x", "t", "y"}}) {
    for (const MonomialOrder& remaining : {MonomialOrder::grevlex(), MonomialOrder::lex(), MonomialOrder::grlex()}) {
      SCOPED_TRACE(variables[0] + variables[1] + variables[2] + " " + remaining.name());
      const EliminationResult r = eliminate_from({"x-t^2", "y-t^3"}, variables, {"t"}, remaining);
      EXPECT_EQ(print_all(r.elimination), (Strings{"x^3-y^2"}));
      EXPECT_EQ(r.remaining_ring->variables(), (std::vector<std::string>{"x", "y"}));
      EXPECT_EQ(r.block_ring->variables(), (std::vector<std::string>{"t", "x", "y"}));
      EXPECT_EQ(r.remaining_ring->order(), remaining);
    }
  }
}

// (s + t, s^2 + t^2, s^3 + t^3): Newton's identities give p3 = e1^3 - 3·e1·e2 with
// e2 = (x^2 - y)/2, so 2z = -x^3 + 3xy.
TEST(EliminationTest, PowerSumsOfTwoParameters) {
  const EliminationResult r =
      eliminate_from({"x-s-t", "y-s^2-t^2", "z-s^3-t^3"}, {"s", "t", "x", "y", "z"}, {"s", "t"});
  EXPECT_EQ(print_all(r.elimination), (Strings{"x^3-3*x*y+2*z"}));
}

// The rational unit circle x = (1 - t^2)/(1 + t^2), y = 2t/(1 + t^2), with the
// denominators cleared; 1 + t^2 has no real root, and over ℂ x·0 = 2 is impossible,
// so no extra component appears.
TEST(EliminationTest, RationalCircle) {
  const EliminationResult r = eliminate_from({"x*(1+t^2)-(1-t^2)", "y*(1+t^2)-2*t"}, {"t", "x", "y"}, {"t"});
  EXPECT_EQ(print_all(r.elimination), (Strings{"x^2+y^2-1"}));
}

// Eliminating from the twisted cubic's ideal one variable at a time gives the plane
// projections: (x, y) ↦ y = x^2, (x, z) ↦ z = x^3, (y, z) ↦ y^3 = z^2.
TEST(EliminationTest, TwistedCubicProjections) {
  const Strings cubic = {"y-x^2", "z-x^3"};
  const std::vector<std::string> vars = {"x", "y", "z"};
  EXPECT_EQ(print_all(eliminate_from(cubic, vars, {"z"}).elimination), (Strings{"x^2-y"}));
  EXPECT_EQ(print_all(eliminate_from(cubic, vars, {"y"}).elimination), (Strings{"x^3-z"}));
  EXPECT_EQ(print_all(eliminate_from(cubic, vars, {"x"}).elimination), (Strings{"y^3-z^2"}));
  // Two of three: nothing is left in one variable alone.
  EXPECT_TRUE(eliminate_from(cubic, vars, {"x", "y"}).elimination.empty());
}

// The elimination order: grevlex on the remaining variables uses Singular's
// (a(1,..,1,0,..,0),dp); any other remaining order the block order (grevlex | order).
TEST(EliminationTest, OrderOfTheBlockRing) {
  // x = st, y = s + t^2, z = t: s = y - z^2, so x = yz - z^3.
  const std::vector<std::string> vars = {"x", "s", "y", "t", "z"};
  const Strings gens = {"x-s*t", "y-s-t^2", "z-t"};
  const EliminationResult lex = eliminate_from(gens, vars, {"s", "t"}, MonomialOrder::lex());
  EXPECT_EQ(lex.block_ring->order(), MonomialOrder::block(2, MonomialOrder::grevlex(), MonomialOrder::lex()));
  EXPECT_EQ(lex.block_ring->variables(), (std::vector<std::string>{"s", "t", "x", "y", "z"}));
  EXPECT_EQ(lex.remaining_ring->order(), MonomialOrder::lex());
  EXPECT_EQ(print_all(lex.elimination), (Strings{"x-y*z+z^3"}));

  const EliminationResult grevlex = eliminate_from(gens, vars, {"s", "t"});
  EXPECT_EQ(grevlex.block_ring->order(), MonomialOrder::weighted({1, 1, 0, 0, 0}, MonomialOrder::grevlex()));
  EXPECT_EQ(grevlex.remaining_ring->order(), MonomialOrder::grevlex());
  EXPECT_EQ(print_all(grevlex.elimination), (Strings{"z^3-y*z+x"}));

  // Both are elimination orders: a monomial with s or t beats every one without.
  for (const RingPtr& ring : {lex.block_ring, grevlex.block_ring}) {
    EXPECT_EQ(to_string(parse_polynomial("x^9*y^9*z^9+t", ring)), "t+x^9*y^9*z^9");
  }
}

TEST(EliminationTest, UnknownVariableIsAnInputError) {
  const RingPtr ring = Ring::make({"t", "x", "y"});
  const std::vector<Polynomial> gs = parse_all({"x-t^2", "y-t^3"}, ring);
  const std::vector<std::string> names = {"t", "z"};
  EXPECT_TRUE(testing::throws_input_error([&] { eliminate(gs, names); }, "unknown_variable"));
  EXPECT_THROW(eliminate({}, std::vector<std::string>{"t"}), std::invalid_argument);
}

// Properties on random ideals in x, y, z, eliminating x, for the remaining orders
// grevlex (weighted elimination order), lex and grlex (block orders (grevlex | R)):
//  - the Gröbner basis in the block ring is reduced and a Gröbner basis;
//  - the elimination basis involves only the remaining variables and consists of
//    exactly the elements of the full basis free of x;
//  - every element lies in the ideal: normal form 0 modulo a Gröbner basis of the
//    generators computed independently in the original ring;
//  - completeness and reducedness through an independent path: block(1, lex, R) is
//    another elimination order for x restricting to R, so the x-free elements of the
//    plain Gröbner basis in it are the same reduced basis of I ∩ ℚ[y, z].
// (Comparing the bases for different R directly would need a basis conversion, and
// from lex that costs minutes on these ideals: the eliminants have degree up to 27.)
TEST(EliminationTest, RandomIdealsSatisfyTheEliminationTheorem) {
  const std::vector<std::string> vars = {"x", "y", "z"};
  const RingPtr ring = Ring::make(vars);
  int non_trivial = 0;
  for (const auto& generators : testing::random_ideals(ring, kNumRandomIdeals)) {
    SCOPED_TRACE(::testing::PrintToString(print_all(generators)));
    const std::optional<GroebnerResult> full = testing::compute_bounded(generators);
    ASSERT_TRUE(full);
    const std::vector<Polynomial>& full_basis = full->basis;
    for (const MonomialOrder& remaining : {MonomialOrder::grevlex(), MonomialOrder::lex(), MonomialOrder::grlex()}) {
      SCOPED_TRACE(remaining.name());
      BuchbergerParams bounded;
      bounded.budget = testing::small_ideal_budget();
      const EliminationResult r = eliminate(generators, std::vector<std::string>{"x"}, bounded, remaining);
      EXPECT_TRUE(is_reduced(r.groebner.basis));
      EXPECT_TRUE(is_groebner(r.groebner.basis));
      ASSERT_EQ(r.remaining_ring->num_variables(), 2u);
      std::size_t free_of_x = 0;
      for (const auto& g : r.groebner.basis) free_of_x += g.involves(0) ? 0 : 1;
      EXPECT_EQ(r.elimination.size(), free_of_x);
      EXPECT_TRUE(is_reduced(r.elimination));
      std::vector<Polynomial> back;
      for (const auto& e : r.elimination) {
        EXPECT_EQ(e.ring(), r.remaining_ring);
        back.push_back(e.map_to(ring, std::vector<std::size_t>{1, 2}));
        EXPECT_FALSE(back.back().involves(0));
      }
      EXPECT_TRUE(testing::all_reduce_to_zero(back, full_basis));

      const RingPtr other_ring = Ring::make(vars, MonomialOrder::block(1, MonomialOrder::lex(), remaining));
      std::vector<Polynomial> other_generators;
      for (const auto& g : generators)
        other_generators.push_back(g.map_to(other_ring, std::vector<std::size_t>{0, 1, 2}));
      Strings expected;
      const std::optional<GroebnerResult> other = testing::compute_bounded(other_generators);
      ASSERT_TRUE(other);
      for (const auto& g : other->basis) {
        if (!g.involves(0)) expected.push_back(to_string(g));
      }
      EXPECT_EQ(print_all(r.elimination), expected);
      if (!r.elimination.empty() && !testing::is_unit_basis(r.elimination)) ++non_trivial;
    }
  }
  EXPECT_GE(non_trivial, 3 * 3 * kNumRandomIdeals / 4);
}

}  // namespace
}  // namespace implicitizer
