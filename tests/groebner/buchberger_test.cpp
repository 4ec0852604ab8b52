/// Tests of lib/src/groebner/buchberger.cpp and s_pair_queue.cpp: known reduced
/// bases (textbook and Singular), edge cases (zero, unit and principal ideals), the
/// budget, and a property sweep over seeded random ideals in which every driver
/// setting must find the same reduced basis. A reduced Gröbner basis is unique for
/// the ideal and order (CLO Thm 2.7.5), so any disagreement between settings means a
/// criterion threw away a pair it needed (or the reduction is wrong), and the slow
/// twins is_groebner()/is_reduced() catch a wrong common answer.

#include "implicitizer/groebner/buchberger.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/division.hpp"
#include "implicitizer/groebner/reduced_basis.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

using testing::parse_all;
using testing::print_all;

constexpr int kNumRandomIdeals = 30;

using Strings = std::vector<std::string>;

// The reduced basis of `generators` (parsed in a ring over `variables`) under
// `order`, printed, after checking the basis and the counters of the default run and
// that every other setting finds the same basis.
Strings reduced_basis_of(const Strings& generators, const std::vector<std::string>& variables,
                         const MonomialOrder& order) {
  const RingPtr ring = Ring::make(variables, order);
  const std::vector<Polynomial> gs = parse_all(generators, ring);
  const GroebnerResult r = compute_groebner_basis(gs);
  EXPECT_TRUE(is_reduced(r.basis));
  EXPECT_TRUE(is_groebner(r.basis));
  EXPECT_TRUE(testing::is_sorted_by_leading_monomial(r.basis));
  EXPECT_TRUE(testing::all_reduce_to_zero(gs, r.basis));
  testing::expect_coherent_stats(r, BuchbergerParams(), gs.size());
  const Strings printed = print_all(r.basis);
  for (const BuchbergerParams& params : testing::all_settings()) {
    SCOPED_TRACE(testing::describe(params));
    const std::optional<GroebnerResult> other = testing::compute_bounded(gs, params);
    if (!other) continue;
    EXPECT_EQ(print_all(other->basis), printed);
    testing::expect_coherent_stats(*other, params, gs.size());
  }
  return printed;
}

// ---- Known answers --------------------------------------------------------------

// The twisted cubic (t, t^2, t^3): in grevlex the three quadrics, listed by
// increasing leading monomial (y^2 < xy < x^2 for x > y > z).
TEST(BuchbergerTest, TwistedCubicGrevlex) {
  EXPECT_EQ(reduced_basis_of({"y-x^2", "z-x^3"}, {"x", "y", "z"}, MonomialOrder::grevlex()),
            (Strings{"y^2-x*z", "x*y-z", "x^2-y"}));
}

// Produced by Singular 4.3 (4.3.1): `ring r = 0, (x,y,z), lp; option(redSB);
// std(ideal(y-x^2, z-x^3))` (resp. `Dp` for grlex), each element made monic.
TEST(BuchbergerTest, TwistedCubicLexAndGrlex) {
  EXPECT_EQ(reduced_basis_of({"y-x^2", "z-x^3"}, {"x", "y", "z"}, MonomialOrder::lex()),
            (Strings{"y^3-z^2", "x*z-y^2", "x*y-z", "x^2-y"}));
  EXPECT_EQ(reduced_basis_of({"y-x^2", "z-x^3"}, {"x", "y", "z"}, MonomialOrder::grlex()),
            (Strings{"x*z-y^2", "x*y-z", "x^2-y", "y^3-z^2"}));
}

// Produced by Singular 4.3: `ring r = 0, (a,b,c), dp;` (resp. `lp`) `option(redSB);
// std(ideal(a+b+c, a*b+b*c+c*a, a*b*c-1))`.
TEST(BuchbergerTest, Cyclic3) {
  const std::vector<std::string> vars = {"a", "b", "c"};
  const RingPtr ring = Ring::make(vars);
  const Strings generators = print_all(testing::cyclic(ring));
  EXPECT_EQ(generators, (Strings{"a+b+c", "a*b+a*c+b*c", "a*b*c-1"}));
  EXPECT_EQ(reduced_basis_of(generators, vars, MonomialOrder::grevlex()), (Strings{"a+b+c", "b^2+b*c+c^2", "c^3-1"}));
  EXPECT_EQ(reduced_basis_of(generators, vars, MonomialOrder::lex()), (Strings{"c^3-1", "b^2+b*c+c^2", "a+b+c"}));
}

// Produced by Singular 4.3: `ring r = 0, (x0,x1,x2,x3), dp;` (resp. `lp`)
// `option(redSB); std(I)` for Katsura-3 I = (x0+2x1+2x2+2x3-1, x0^2+2x1^2+2x2^2+2x3^2-x0,
// 2x0x1+2x1x2+2x2x3-x1, 2x0x2+x1^2+2x1x3-x2), each element divided by its leading
// coefficient.
TEST(BuchbergerTest, Katsura3) {
  const std::vector<std::string> vars = {"x0", "x1", "x2", "x3"};
  const RingPtr ring = Ring::make(vars);
  const Strings generators = print_all(testing::katsura(ring));
  EXPECT_EQ(generators, (Strings{"x0+2*x1+2*x2+2*x3-1", "x0^2+2*x1^2+2*x2^2+2*x3^2-x0", "2*x0*x1+2*x1*x2+2*x2*x3-x1",
                                 "x1^2+2*x0*x2+2*x1*x3-x2"}));
  EXPECT_EQ(reduced_basis_of(generators, vars, MonomialOrder::grevlex()),
            (Strings{
                "x0+2*x1+2*x2+2*x3-1",
                "x2^2+2*x1*x3+32/7*x2*x3+27/7*x3^2-1/7*x1-4/7*x2-9/7*x3",
                "x1*x2-2*x1*x3-23/7*x2*x3-24/7*x3^2+1/14*x1+2/7*x2+8/7*x3",
                "x1^2+2*x1*x3+8/7*x2*x3+12/7*x3^2-2/7*x1-1/7*x2-4/7*x3",
                "x2*x3^2+10/9*x3^3-1/18*x1*x3-17/81*x2*x3-13/27*x3^2+1/54*x1+5/162*x2+1/27*x3",
                "x1*x3^2-1/3*x3^3-1/9*x1*x3+1/54*x2*x3+1/9*x3^2-1/36*x1-1/27*x2",
                "x3^4-362/891*x3^3+37/891*x1*x3+1841/16038*x2*x3+206/2673*x3^2-13/10692*x1-389/32076*x2-47/2673*x3",
            }));
  EXPECT_EQ(reduced_basis_of(generators, vars, MonomialOrder::lex()),
            (Strings{
                "x3^8-8/11*x3^7+4/33*x3^6+131/5346*x3^5-70/8019*x3^4+1/3564*x3^3+5/42768*x3^2-1/128304*x3",
                "x2+123812761248/1971025*x3^7-79183342368/1971025*x3^6+7548646608/1971025*x3^5+3840228724/"
                "1971025*x3^4-2024910556/5913075*x3^3-132524276/5913075*x3^2+30947828/5913075*x3",
                "x1-97197721632/1971025*x3^7+73975630752/1971025*x3^6-12121915032/1971025*x3^5-2760941496/"
                "1971025*x3^4+814792828/1971025*x3^3-1678512/1971025*x3^2-9158924/1971025*x3",
                "x0-53230079232/1971025*x3^7+10415423232/1971025*x3^6+9146536848/1971025*x3^5-2158574456/"
                "1971025*x3^4-838935856/5913075*x3^3+275119624/5913075*x3^2+4884038/5913075*x3-1",
            }));
}

// ---- Edge cases -----------------------------------------------------------------

TEST(BuchbergerTest, NoGeneratorsAndZeroGeneratorsGiveTheEmptyBasis) {
  const RingPtr ring = Ring::make({"x", "y"});
  const GroebnerResult none = compute_groebner_basis({});
  EXPECT_TRUE(none.basis.empty());
  EXPECT_EQ(none.stats.basis_size, 0u);

  const std::vector<Polynomial> zeros = {Polynomial(ring), Polynomial(ring)};
  const GroebnerResult zero_ideal = compute_groebner_basis(zeros);
  EXPECT_TRUE(zero_ideal.basis.empty());
  EXPECT_EQ(zero_ideal.stats.basis_size, 0u);
  EXPECT_EQ(zero_ideal.stats.pairs_created, 0u);

  // Zero generators among others are ignored.
  const std::vector<Polynomial> mixed = {Polynomial(ring), parse_polynomial("2*x^2-4*y", ring), Polynomial(ring)};
  EXPECT_EQ(print_all(compute_groebner_basis(mixed).basis), (Strings{"x^2-2*y"}));
}

// A constant generator, or a constant that only appears after reductions, gives {1}
// in every setting.
TEST(BuchbergerTest, UnitIdealGivesOne) {
  const RingPtr ring = Ring::make({"x", "y", "z"});
  for (const Strings& generators : {Strings{"x^2+y", "-3/5"}, Strings{"x*y-1", "x"}, Strings{"x", "x+1"},
                                    Strings{"x^2-y", "x^2-y+7"}, Strings{"x*y+z", "x^2", "y^2", "z-1"}}) {
    const std::vector<Polynomial> gs = parse_all(generators, ring);
    for (const BuchbergerParams& params : testing::all_settings()) {
      SCOPED_TRACE(generators.front() + ", ... with " + testing::describe(params));
      const GroebnerResult r = compute_groebner_basis(gs, params);
      EXPECT_EQ(print_all(r.basis), (Strings{"1"}));
      testing::expect_coherent_stats(r, params, gs.size());
    }
  }
}

// A principal ideal's reduced basis is its generator made monic, whatever the order.
TEST(BuchbergerTest, PrincipalIdealGivesMonicGenerator) {
  for (const auto& [name, order] : testing::property_orders()) {
    SCOPED_TRACE(name);
    const RingPtr ring = Ring::make({"x", "y", "z"}, order);
    const Polynomial g = parse_polynomial("-6*x^2*y+4/3*z^3-2*x+10", ring);
    const GroebnerResult r = compute_groebner_basis(std::vector<Polynomial>{g});
    ASSERT_EQ(r.basis.size(), 1u);
    EXPECT_EQ(r.basis[0], g.monic());
    EXPECT_EQ(r.basis[0].leading_coefficient(), Rational(1));
    // The same ideal given redundantly: multiples of g add nothing.
    const std::vector<Polynomial> redundant = {g * parse_polynomial("x-y", ring), g.scaled(Rational(5)), g * g};
    EXPECT_EQ(compute_groebner_basis(redundant).basis, r.basis);
  }
}

// Generators that are already a reduced basis come back unchanged (made monic).
TEST(BuchbergerTest, MonomialIdealIsItsOwnBasis) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, MonomialOrder::lex());
  const std::vector<Polynomial> gs = parse_all({"3*x^2*y", "y^3", "x*z^2", "x^3*y*z"}, ring);
  const GroebnerResult r = compute_groebner_basis(gs);
  // x^3yz is a multiple of x^2y and drops out.
  EXPECT_EQ(print_all(r.basis), (Strings{"y^3", "x*z^2", "x^2*y"}));
}

TEST(BuchbergerTest, GeneratorsFromDifferentRingsAreRejected) {
  const RingPtr a = Ring::make({"x", "y"});
  const RingPtr b = Ring::make({"x", "y"}, MonomialOrder::lex());
  const std::vector<Polynomial> gs = {parse_polynomial("x", a), parse_polynomial("y", b)};
  EXPECT_THROW(compute_groebner_basis(gs), std::invalid_argument);
  // Equal rings built separately are the same ring.
  const RingPtr c = Ring::make({"x", "y"});
  const std::vector<Polynomial> same = {parse_polynomial("x^2-y", a), parse_polynomial("x*y-1", c)};
  EXPECT_NO_THROW(compute_groebner_basis(same));
}

// ---- Sugar-strategy regressions ---------------------------------------------------

// Tiny ideals on which the sugar strategy swelled coefficients for seconds to
// minutes (Singular 4.3 answers each in 40 ms), found while building the sweep:
//  - in lex, (4x^3 + 3x^2y, -4x^2 + 5xz - 3x + 3z^3, 2y^2) with sugar and
//    Gebauer–Möller: over 20 s, through elements in z alone of degree 35, 34, ...
//    whose coefficients doubled at each step (millions of bits), as Katsura-3 in lex
//    (over 60 s);
//  - the unit ideal (-3xy^2, -x^2y - 4y^2 + 3yz - 2z^2, x^2 - 5y^2z + xz - 4y,
//    -2xz^2 - yz^2 - y + 2) (Singular: `std` gives 1) in block(2: grlex | lex), where
//    `automatic` picks sugar: over 3 s.
// The cause of the Gebauer–Möller cases was the driver dropping elements made
// redundant from the reducers: reductions then went through the element of high
// sugar that replaced them (see rebuild_reducers in buchberger.cpp). What is left is
// sugar with no chain criterion at all on the unit ideal (over 2 s).
struct SugarRegression {
  const char* name;
  MonomialOrder order;
  Strings generators;
};

std::vector<SugarRegression> sugar_regressions() {
  return {{"lex", MonomialOrder::lex(), {"4*x^3+3*x^2*y", "-4*x^2+5*x*z-3*x+3*z^3", "2*y^2"}},
          {"block(2:grlex|lex)",
           MonomialOrder::block(2, MonomialOrder::grlex(), MonomialOrder::lex()),
           {"-3*x*y^2", "-x^2*y-4*y^2+3*y*z-2*z^2", "x^2-5*y^2*z+x*z-4*y", "-2*x*z^2-y*z^2-y+2"}}};
}

bool is_sugar_without_chain_criterion(const BuchbergerParams& params) {
  return params.variant.strategy == SelectionStrategy::sugar && params.variant.chain_criterion == ChainCriterion::off;
}

// Every setting but sugar without a chain criterion finishes at once, and they agree.
TEST(BuchbergerTest, SugarRegressionIdealsFinishQuickly) {
  for (const SugarRegression& ideal : sugar_regressions()) {
    SCOPED_TRACE(ideal.name);
    const std::vector<Polynomial> gs = parse_all(ideal.generators, Ring::make({"x", "y", "z"}, ideal.order));
    std::optional<Strings> expected;
    for (const BuchbergerParams& params : testing::all_settings()) {
      if (is_sugar_without_chain_criterion(params)) continue;
      SCOPED_TRACE(testing::describe(params));
      const std::optional<GroebnerResult> r = testing::compute_bounded(gs, params);
      if (!r) continue;
      EXPECT_TRUE(is_groebner(r->basis));
      EXPECT_TRUE(is_reduced(r->basis));
      if (!expected) expected = print_all(r->basis);
      EXPECT_EQ(print_all(r->basis), *expected);
    }
  }
}

// Disabled until sugar without a chain criterion stops swelling on the unit ideal
// above (slowness, not a wrong answer: given time, the basis is right). Run it with
// --gtest_also_run_disabled_tests.
TEST(BuchbergerTest, DISABLED_SugarWithoutChainCriterionFinishesQuickly) {
  for (const SugarRegression& ideal : sugar_regressions()) {
    SCOPED_TRACE(ideal.name);
    const std::vector<Polynomial> gs = parse_all(ideal.generators, Ring::make({"x", "y", "z"}, ideal.order));
    for (const BuchbergerParams& params : testing::all_settings()) {
      if (!is_sugar_without_chain_criterion(params)) continue;
      SCOPED_TRACE(testing::describe(params));
      testing::compute_bounded(gs, params);
    }
  }
}

// ---- Budget ---------------------------------------------------------------------

// Katsura-5 in lex: over two minutes of work (for Singular 4.3's `std` in `lp` too),
// far more than any limit below, yet small generators.
std::vector<Polynomial> hard_ideal() {
  return testing::katsura(Ring::make({"u0", "u1", "u2", "u3", "u4", "u5"}, MonomialOrder::lex()));
}

// Runs `params` on the hard ideal and returns the limit that stopped it.
std::optional<Limit> stopping_limit(const BuchbergerParams& params) {
  try {
    compute_groebner_basis(hard_ideal(), params);
  } catch (const LimitExceeded& e) {
    EXPECT_FALSE(std::string(e.what()).empty());
    return e.limit();
  }
  return std::nullopt;
}

TEST(BuchbergerBudgetTest, TimeoutStopsWithTimeLimit) {
  BuchbergerParams params;
  params.budget = Budget::with_timeout(0.02);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(stopping_limit(params), Limit::time);
  // It stopped soon after the deadline, not at the end of the computation (minutes):
  // the bound leaves room for a loaded machine.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}

TEST(BuchbergerBudgetTest, TermLimitStopsWithSizeLimit) {
  BuchbergerParams params;
  params.budget.set_max_terms(12);
  EXPECT_EQ(stopping_limit(params), Limit::size);
}

TEST(BuchbergerBudgetTest, CancelBeforeStartStopsWithCancelled) {
  BuchbergerParams params;
  params.budget.cancel();
  EXPECT_EQ(stopping_limit(params), Limit::cancelled);
}

// A copy of the budget shares the cancellation flag: another thread can stop a
// running computation, as the server does.
TEST(BuchbergerBudgetTest, CancelFromAnotherThreadStopsWithCancelled) {
  BuchbergerParams params;
  const Budget handle = params.budget;
  std::thread canceller([handle] {
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    handle.cancel();
  });
  const auto start = std::chrono::steady_clock::now();
  const std::optional<Limit> limit = stopping_limit(params);
  canceller.join();
  EXPECT_EQ(limit, Limit::cancelled);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}

// Limits that are never reached change nothing.
TEST(BuchbergerBudgetTest, GenerousBudgetGivesTheSameBasis) {
  const RingPtr ring = Ring::make({"x0", "x1", "x2", "x3"});
  const std::vector<Polynomial> gs = testing::katsura(ring);
  BuchbergerParams params;
  params.budget = Budget::with_timeout(600);
  params.budget.set_max_terms(1000);
  EXPECT_EQ(compute_groebner_basis(gs, params).basis, compute_groebner_basis(gs).basis);
}

// ---- Property sweep -------------------------------------------------------------

// The random ideals of the sweep, in `ring` (the same ideals for every order).
std::vector<std::vector<Polynomial>> random_ideals(const RingPtr& ring) {
  return testing::random_ideals(ring, kNumRandomIdeals);
}

class BuchbergerPropertyTest : public ::testing::TestWithParam<testing::NamedOrder> {};

// Every strategy × chain criterion × product criterion (and tail reduction off)
// finds the same reduced basis, which the slow twins accept, which contains the
// generators' ideal, and whose counters add up.
TEST_P(BuchbergerPropertyTest, EverySettingGivesTheSameReducedBasis) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, GetParam().order);
  const std::vector<BuchbergerParams> settings = testing::all_settings();
  int non_trivial = 0;
  for (const auto& generators : random_ideals(ring)) {
    SCOPED_TRACE("ideal " + ::testing::PrintToString(print_all(generators)));
    const std::optional<GroebnerResult> bounded = testing::compute_bounded(generators);
    ASSERT_TRUE(bounded);
    const GroebnerResult& reference = *bounded;
    const Strings expected = print_all(reference.basis);
    ASSERT_FALSE(reference.basis.empty());
    EXPECT_TRUE(is_reduced(reference.basis));
    EXPECT_TRUE(is_groebner(reference.basis));
    EXPECT_TRUE(testing::is_sorted_by_leading_monomial(reference.basis));
    EXPECT_TRUE(testing::all_reduce_to_zero(generators, reference.basis));
    for (const auto& g : reference.basis) EXPECT_TRUE(g.is_canonical()) << to_string(g);
    if (!testing::is_unit_basis(reference.basis) && reference.stats.reductions > 0) ++non_trivial;
    for (const BuchbergerParams& params : settings) {
      SCOPED_TRACE(testing::describe(params));
      const std::optional<GroebnerResult> r = testing::compute_bounded(generators, params);
      if (!r) continue;
      EXPECT_EQ(print_all(r->basis), expected);
      testing::expect_coherent_stats(*r, params, generators.size());
    }
  }
  // The sweep means something only if most ideals needed actual work.
  EXPECT_GE(non_trivial, kNumRandomIdeals / 2);
}

// The criteria exist to save reductions: on the whole sweep, Gebauer–Möller with the
// product criterion reduces no more S-pairs than no criterion at all, and removes
// some. (Per ideal this is not a theorem, so only the total is checked.)
TEST_P(BuchbergerPropertyTest, CriteriaSaveReductions) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, GetParam().order);
  BuchbergerParams none;
  none.variant.chain_criterion = ChainCriterion::off;
  none.variant.product_criterion = false;
  const BuchbergerParams all;
  std::size_t with_none = 0, with_all = 0, removed = 0;
  for (const auto& generators : random_ideals(ring)) {
    const std::optional<GroebnerResult> without = testing::compute_bounded(generators, none);
    const std::optional<GroebnerResult> with = testing::compute_bounded(generators, all);
    ASSERT_TRUE(without && with);
    with_none += without->stats.reductions;
    const BuchbergerStats& s = with->stats;
    with_all += s.reductions;
    removed += s.product_criterion + s.chain_criterion;
  }
  EXPECT_LT(with_all, with_none);
  EXPECT_GT(removed, 0u);
}

// The reduced bases of one ideal under two orders generate the same ideal: each
// element of one has normal form 0 modulo the other.
TEST_P(BuchbergerPropertyTest, BasesForDifferentOrdersGenerateTheSameIdeal) {
  const RingPtr ring = Ring::make({"x", "y", "z"}, GetParam().order);
  const RingPtr grevlex = Ring::make({"x", "y", "z"});
  const std::vector<std::size_t> identity = {0, 1, 2};
  for (const auto& generators : random_ideals(ring)) {
    SCOPED_TRACE("ideal " + ::testing::PrintToString(print_all(generators)));
    const std::optional<GroebnerResult> in_ring = testing::compute_bounded(generators);
    ASSERT_TRUE(in_ring);
    const std::vector<Polynomial>& basis = in_ring->basis;
    std::vector<Polynomial> in_grevlex;
    for (const auto& g : generators) in_grevlex.push_back(g.map_to(grevlex, identity));
    const std::optional<GroebnerResult> in_other = testing::compute_bounded(in_grevlex);
    ASSERT_TRUE(in_other);
    const std::vector<Polynomial>& other = in_other->basis;
    std::vector<Polynomial> basis_in_grevlex, other_in_ring;
    for (const auto& g : basis) basis_in_grevlex.push_back(g.map_to(grevlex, identity));
    for (const auto& g : other) other_in_ring.push_back(g.map_to(ring, identity));
    EXPECT_TRUE(testing::all_reduce_to_zero(basis_in_grevlex, other));
    EXPECT_TRUE(testing::all_reduce_to_zero(other_in_ring, basis));
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, BuchbergerPropertyTest, ::testing::ValuesIn(testing::property_orders()),
                         [](const ::testing::TestParamInfo<testing::NamedOrder>& order) { return order.param.name; });

}  // namespace
}  // namespace implicitizer
