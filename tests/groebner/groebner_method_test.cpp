/// Tests of lib/src/groebner/groebner_method.cpp: the method names, that every method
/// gives the same reduced basis (and elimination), that the route says what answered,
/// and that `auto` lets the caller's own limits through rather than switching routes.

#include "implicitizer/groebner/groebner_method.hpp"

#include <gtest/gtest.h>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

using testing::parse_all;
using testing::print_all;

TEST(GroebnerMethodTest, NamesRoundTripAndUnknownNamesAreRefused) {
  for (GroebnerMethod m :
       {GroebnerMethod::automatic, GroebnerMethod::buchberger, GroebnerMethod::modular, GroebnerMethod::f4}) {
    EXPECT_EQ(parse_groebner_method(to_string(m)), m);
  }
  try {
    parse_groebner_method("magic");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "unknown_method");
    EXPECT_EQ(e.field(), "method");
  }
}

TEST(GroebnerMethodTest, EveryMethodGivesTheSameBasisAndSaysWhichAnswered) {
  const RingPtr ring = Ring::make({"x", "y"}, MonomialOrder::lex());
  const std::vector<Polynomial> generators = parse_all({"x^2+y", "y^2-x"}, ring);
  const std::vector<std::string> expected = print_all(compute_groebner_basis(generators).basis);
  GroebnerRoute route;
  // A small ideal: Buchberger answers within auto's head start.
  EXPECT_EQ(print_all(compute_groebner_basis_by_method(generators, GroebnerMethod::automatic, {}, &route).basis),
            expected);
  EXPECT_EQ(route.method, GroebnerMethod::buchberger);
  EXPECT_FALSE(route.modular.has_value());
  EXPECT_EQ(print_all(compute_groebner_basis_by_method(generators, GroebnerMethod::modular, {}, &route).basis),
            expected);
  EXPECT_EQ(route.method, GroebnerMethod::modular);
  ASSERT_TRUE(route.modular.has_value());
  EXPECT_TRUE(route.modular->proven);
  EXPECT_EQ(print_all(compute_groebner_basis_by_method(generators, GroebnerMethod::f4, {}, &route).basis), expected);
  EXPECT_EQ(route.method, GroebnerMethod::f4);
  ASSERT_TRUE(route.modular.has_value());
  EXPECT_TRUE(route.modular->proven);
}

// Katsura-6 needs more than the head start's work over ℚ (work is counted, not
// timed: the same on every run): auto hands over to the F4 route, which proves the
// basis the modular route with Buchberger finds.
TEST(GroebnerMethodTest, AutoHandsLargeIdealsToF4) {
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5", "u6"});
  const std::vector<Polynomial> generators = testing::katsura(ring);
  GroebnerRoute route;
  const auto f4 = print_all(compute_groebner_basis_by_method(generators, GroebnerMethod::automatic, {}, &route).basis);
  EXPECT_EQ(route.method, GroebnerMethod::f4);
  ASSERT_TRUE(route.modular.has_value());
  EXPECT_TRUE(route.modular->proven);
  EXPECT_EQ(f4, print_all(compute_groebner_basis_by_method(generators, GroebnerMethod::modular, {}).basis));
}

TEST(GroebnerMethodTest, EliminationByEveryMethodAgrees) {
  const RingPtr ring = Ring::make({"s", "t", "x", "y", "z"});
  const std::vector<Polynomial> generators = parse_all({"x-s-t", "y-s*t", "z-s^2"}, ring);
  const std::vector<std::string> names = {"s", "t"};
  for (GroebnerMethod m :
       {GroebnerMethod::automatic, GroebnerMethod::buchberger, GroebnerMethod::modular, GroebnerMethod::f4}) {
    GroebnerRoute route;
    const EliminationResult r = eliminate_by_method(generators, names, m, {}, MonomialOrder::grevlex(), &route);
    EXPECT_EQ(print_all(r.elimination), (std::vector<std::string>{"x^2*z-y^2-2*y*z-z^2"})) << to_string(m);
    EXPECT_EQ(route.method, m == GroebnerMethod::automatic ? GroebnerMethod::buchberger : m);
  }
}

TEST(GroebnerMethodTest, AutoLetsTheCallersDeadlineThrough) {
  // Only the head start's work allowance hands over to the modular route: a deadline
  // that has passed stops auto with the time limit, not with a switch of route.
  const RingPtr ring = Ring::make({"u0", "u1", "u2", "u3", "u4", "u5"});
  BuchbergerParams params;
  params.budget.set_timeout(1e-6);
  while (params.budget.seconds_left() > 0) {
    // Waits on the budget's own clock until the deadline has passed: no sleep.
  }
  try {
    compute_groebner_basis_by_method(testing::katsura(ring), GroebnerMethod::automatic, params);
    FAIL() << "no LimitExceeded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
}

}  // namespace
}  // namespace implicitizer
