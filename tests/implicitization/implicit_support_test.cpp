// Tests of lib/src/implicitization/implicit_support.cpp: Bernstein's mixed volumes on
// polygons whose counts are known by hand, and the predicted box and classes against
// the answers of ../shared/bench/expected (the equation lies in the box and in one
// class).

#include "implicitizer/implicitization/implicit_support.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "implicitization/surfaces.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"

namespace implicitizer {
namespace {

const std::string kBench = std::string(IMPLICITIZER_SHARED_DIR) + "/bench";

using Points = std::vector<std::array<std::int64_t, 2>>;

TEST(MixedVolume, BezoutKouchnirenkoAndSegments) {
  const Points triangle3{{0, 0}, {3, 0}, {0, 3}};
  EXPECT_EQ(mixed_volume(triangle3, triangle3), 9);  // Bézout: two general cubics meet in 9 points
  const Points square2{{0, 0}, {2, 0}, {0, 2}, {2, 2}};
  const Points square3{{0, 0}, {3, 0}, {0, 3}, {3, 3}};
  EXPECT_EQ(mixed_volume(square2, square3), 12);  // bidegrees (2,2) and (3,3): 2·3 + 2·3
  // s^7 + t − a and t^7 + s − b: 49 common zeros, all in the torus.
  EXPECT_EQ(mixed_volume({{0, 0}, {7, 0}, {0, 1}}, {{0, 0}, {0, 7}, {1, 0}}), 49);
  // Against a segment: the lattice width of the other polygon across it.
  EXPECT_EQ(mixed_volume({{0, 0}, {0, 7}, {1, 0}}, {{0, 0}, {1, 3}}), 10);
  EXPECT_EQ(mixed_volume({{0, 0}, {1, 3}}, {{0, 0}, {2, 6}}), 0);  // parallel segments
  // Interior and repeated points change nothing.
  EXPECT_EQ(mixed_volume({{0, 0}, {3, 0}, {0, 3}, {1, 1}, {1, 1}}, triangle3), 9);
}

// Every monomial of `answer` (a bench answer) in the box, all in one class.
void expect_in_one_class(const ImplicitSupport& support, const std::string& answer) {
  const Polynomial f = parse_polynomial(answer, space_ring());
  std::map<std::vector<std::int32_t>, std::size_t> class_of;
  for (std::size_t c = 0; c < support.classes.size(); ++c) {
    const auto& e = support.classes[c];
    for (std::size_t i = 0; i < e.size(); i += 3) class_of.emplace(std::vector<std::int32_t>(&e[i], &e[i] + 3), c);
  }
  std::set<std::size_t> classes;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const auto it = class_of.find(f.exponents(t));
    ASSERT_NE(it, class_of.end()) << "a monomial of the answer outside the box";
    classes.insert(it->second);
  }
  EXPECT_EQ(classes.size(), 1u);
  for (std::size_t v = 0; v < 3; ++v) EXPECT_GE(support.degree_in[v], f.degree_in(v));
  EXPECT_GE(support.total_degree, f.total_degree());
}

TEST(PredictImplicitSupport, SparseS7t7HasTheExactBoxAnd48Classes) {
  const auto support = predict_implicit_support(parse_parametrization("s^7+t", "t^7+s", "s*t^3"));
  ASSERT_TRUE(support);
  EXPECT_EQ(support->degree_in, (std::array<std::int32_t, 3>{10, 22, 49}));
  EXPECT_EQ(support->total_degree, 49);
  EXPECT_EQ(support->group_order, 48u);
  EXPECT_EQ(support->classes.size(), 48u);
  EXPECT_EQ(support->columns, 8602u);
  std::size_t sum = 0;
  for (const auto& c : support->classes) sum += c.size() / 3;
  EXPECT_EQ(sum, support->columns);
  EXPECT_LE(support->largest_class, 200u);
  expect_in_one_class(*support, testing::read_text(kBench + "/expected/sparse_s7t7.txt"));
}

TEST(PredictImplicitSupport, ContainsEveryPublicAnswer) {
  for (const auto& s : testing::read_surfaces(kBench + "/surfaces_public.json")) {
    SCOPED_TRACE(s.name);
    const Parametrization p = parse_parametrization(s.x, s.y, s.z);
    const auto support = predict_implicit_support(p);
    if (p.parameter_ring->num_variables() != 2) {
      EXPECT_FALSE(support);
      continue;
    }
    ASSERT_TRUE(support);
    expect_in_one_class(*support, testing::read_text(kBench + "/expected/" + s.name + ".txt"));
  }
}

TEST(PredictImplicitSupport, DensePatchesGainNothing) {
  // A random bidegree-(2,2) patch: the box is the dense one of degree 8, one class.
  for (const auto& s : testing::read_surfaces(kBench + "/surfaces_hard.json")) {
    if (s.name != "tp_22") continue;
    const auto support = predict_implicit_support(parse_parametrization(s.x, s.y, s.z));
    ASSERT_TRUE(support);
    EXPECT_EQ(support->total_degree, 8);
    EXPECT_EQ(support->group_order, 1u);
    EXPECT_EQ(support->classes.size(), 1u);
    EXPECT_EQ(support->columns, 165u);  // C(8 + 3, 3)
  }
}

// The request fuzzer's surface: its box is enumerated monomial by monomial, long
// enough to outlast a short deadline, so the enumeration checks the budget and a
// cancelled one stops it, naming the phase.
TEST(PredictImplicitSupport, EnumeratingALargeBoxChecksTheBudget) {
  const Parametrization p = parse_parametrization("s^40+t", "t^30+s", "s*t");
  const auto support = predict_implicit_support(p);
  ASSERT_TRUE(support);
  EXPECT_GT(support->columns, 1000000u);
  Budget cancelled;
  cancelled.cancel();
  try {
    (void)predict_implicit_support(p, cancelled);
    ADD_FAILURE() << "the enumeration did not check the budget";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
    EXPECT_NE(std::string(e.what()).find("the predicted support"), std::string::npos) << e.what();
  }
}

// Exponents near the parser's limit give degree bounds in the millions: the box is
// refused from its size, counted only as far as kMaxPredictedBox (counted in full it
// did not finish in 30 s, and `implicitize --timeout 1` did not stop).
TEST(PredictImplicitSupport, AnEnormousBoxIsRefusedWithoutCountingIt) {
  const Parametrization p = parse_parametrization("s^1000+t^999", "t^1000+s^997", "s^500*t^501");
  EXPECT_FALSE(predict_implicit_support(p));
}

TEST(PredictImplicitSupport, OnlySurfacesInTwoParameters) {
  EXPECT_FALSE(predict_implicit_support(parse_parametrization({"t^2", "t^3"})));
  EXPECT_FALSE(predict_implicit_support(parse_parametrization("s+u", "t", "s*t*u")));
  EXPECT_FALSE(predict_implicit_support(parse_parametrization("s", "t", "0")));
}

}  // namespace
}  // namespace implicitizer
