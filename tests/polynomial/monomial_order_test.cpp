// Tests of MonomialOrder (lib/src/polynomial/monomial_order.cpp) through the Ring
// that turns it into keys: textbook examples, the axioms of a monomial order on random
// exponent vectors, and agreement with slow, direct definitions of each order.

#include "implicitizer/polynomial/monomial_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "polynomial/test_support.hpp"

namespace implicitizer {
namespace {

using Exponents = std::vector<std::int32_t>;

int sign(long v) { return (v > 0) - (v < 0); }

// The slow twins: each order straight from its definition (Cox–Little–O'Shea §2.2).
int compare_lex(const Exponents& a, const Exponents& b, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i) {
    if (a[i] != b[i]) return sign(long{a[i]} - b[i]);
  }
  return 0;
}

long degree(const Exponents& a, std::size_t from, std::size_t to) {
  return std::accumulate(a.begin() + static_cast<long>(from), a.begin() + static_cast<long>(to), 0L);
}

int compare_kind(MonomialOrder::Kind kind, const Exponents& a, const Exponents& b, std::size_t from, std::size_t to) {
  switch (kind) {
    case MonomialOrder::Kind::lex:
      return compare_lex(a, b, from, to);
    case MonomialOrder::Kind::grlex:
      if (degree(a, from, to) != degree(b, from, to)) return sign(degree(a, from, to) - degree(b, from, to));
      return compare_lex(a, b, from, to);
    case MonomialOrder::Kind::grevlex:
      if (degree(a, from, to) != degree(b, from, to)) return sign(degree(a, from, to) - degree(b, from, to));
      // The last variable where they differ decides: the smaller exponent is the larger monomial.
      for (std::size_t i = to; i-- > from;) {
        if (a[i] != b[i]) return a[i] < b[i] ? 1 : -1;
      }
      return 0;
    default:
      ADD_FAILURE() << "not a basic kind";
      return 0;
  }
}

// An order together with its slow twin. The public API describes weighted and block
// orders only through their kind, weights and block size, so each spec is built from
// known parts and its twin composes the basic definitions above.
struct OrderSpec {
  MonomialOrder order;
  std::function<int(const Exponents&, const Exponents&)> reference;
};

std::vector<OrderSpec> specs(std::size_t n) {
  using K = MonomialOrder::Kind;
  std::vector<OrderSpec> out;
  for (K k : {K::lex, K::grlex, K::grevlex}) {
    MonomialOrder o = k == K::lex     ? MonomialOrder::lex()
                      : k == K::grlex ? MonomialOrder::grlex()
                                      : MonomialOrder::grevlex();
    out.push_back({o, [k, n](const Exponents& a, const Exponents& b) { return compare_kind(k, a, b, 0, n); }});
  }
  std::vector<int> weights(n);
  for (std::size_t i = 0; i < n; ++i) weights[i] = static_cast<int>((3 * i + 1) % 4);  // 1, 0, 3, 2, ...
  for (K tie : {K::lex, K::grevlex}) {
    const MonomialOrder t = tie == K::lex ? MonomialOrder::lex() : MonomialOrder::grevlex();
    out.push_back({MonomialOrder::weighted(weights, t), [weights, tie, n](const Exponents& a, const Exponents& b) {
                     long wa = 0, wb = 0;
                     for (std::size_t i = 0; i < n; ++i) {
                       wa += long{weights[i]} * a[i];
                       wb += long{weights[i]} * b[i];
                     }
                     if (wa != wb) return sign(wa - wb);
                     return compare_kind(tie, a, b, 0, n);
                   }});
  }
  for (std::size_t k : {std::size_t{1}, std::size_t{2}, n - 1}) {
    for (auto [first, rest] :
         {std::pair{K::grevlex, K::grevlex}, std::pair{K::lex, K::grlex}, std::pair{K::grlex, K::lex}}) {
      auto make = [](K kind) {
        return kind == K::lex     ? MonomialOrder::lex()
               : kind == K::grlex ? MonomialOrder::grlex()
                                  : MonomialOrder::grevlex();
      };
      out.push_back({MonomialOrder::block(k, make(first), make(rest)),
                     [k, first, rest, n](const Exponents& a, const Exponents& b) {
                       const int c = compare_kind(first, a, b, 0, k);
                       return c != 0 ? c : compare_kind(rest, a, b, k, n);
                     }});
    }
  }
  return out;
}

int compare(const Ring& ring, const Exponents& a, const Exponents& b) {
  std::vector<std::int32_t> ma(ring.monomial_size()), mb(ring.monomial_size());
  ring.encode(a.data(), ma.data());
  ring.encode(b.data(), mb.data());
  return ring.compare(ma.data(), mb.data());
}

TEST(MonomialOrder, TextbookExamplesInXYZ) {
  // Cox–Little–O'Shea, §2.2, with x > y > z.
  const RingPtr lex = Ring::make({"x", "y", "z"}, MonomialOrder::lex());
  const RingPtr grlex = Ring::make({"x", "y", "z"}, MonomialOrder::grlex());
  const RingPtr grevlex = Ring::make({"x", "y", "z"}, MonomialOrder::grevlex());
  const Exponents x = {1, 0, 0}, y5 = {0, 5, 0}, xz2 = {1, 0, 2}, y3 = {0, 3, 0};
  const Exponents a = {1, 2, 4}, b = {1, 1, 5}, c = {1, 5, 2}, d = {4, 1, 3};

  EXPECT_EQ(compare(*lex, x, y5), 1);
  EXPECT_EQ(compare(*grlex, x, y5), -1);
  EXPECT_EQ(compare(*grevlex, x, y5), -1);

  // Same degree 3: grevlex looks at z first, and the smaller z exponent wins.
  EXPECT_EQ(compare(*grevlex, y3, xz2), 1);
  EXPECT_EQ(compare(*grlex, y3, xz2), -1);
  EXPECT_EQ(compare(*lex, y3, xz2), -1);

  // x y^2 z^4 vs x y z^5 (degree 7 each).
  EXPECT_EQ(compare(*grlex, a, b), 1);
  EXPECT_EQ(compare(*grevlex, a, b), 1);
  // x y^5 z^2 vs x^4 y z^3 (degree 8 each): grlex and grevlex disagree.
  EXPECT_EQ(compare(*grlex, c, d), -1);
  EXPECT_EQ(compare(*grevlex, c, d), 1);
  EXPECT_EQ(compare(*lex, c, d), -1);
}

TEST(MonomialOrder, GrevlexDiffersFromGrlexFromThreeVariables) {
  // x z vs y^2: grlex says x z > y^2, grevlex y^2 > x z.
  const Exponents xz = {1, 0, 1}, y2 = {0, 2, 0};
  EXPECT_EQ(compare(*Ring::make({"x", "y", "z"}, MonomialOrder::grlex()), xz, y2), 1);
  EXPECT_EQ(compare(*Ring::make({"x", "y", "z"}, MonomialOrder::grevlex()), xz, y2), -1);
}

TEST(MonomialOrder, BlockOrderEliminatesTheFirstBlock) {
  // Variables s, t | x, y, z: any monomial with s or t beats any monomial without.
  const RingPtr ring = Ring::make({"s", "t", "x", "y", "z"},
                                  MonomialOrder::block(2, MonomialOrder::grevlex(), MonomialOrder::grevlex()));
  const Exponents t = {0, 1, 0, 0, 0}, big = {0, 0, 9, 9, 9};
  EXPECT_EQ(compare(*ring, t, big), 1);
}

TEST(MonomialOrder, WeightsComeFirst) {
  const RingPtr ring = Ring::make({"x", "y"}, MonomialOrder::weighted({1, 3}, MonomialOrder::lex()));
  EXPECT_EQ(compare(*ring, {2, 0}, {0, 1}), -1);  // weight 2 < 3
  EXPECT_EQ(compare(*ring, {3, 0}, {0, 1}), 1);   // tie on weight 3, lex: x^3 > y
}

TEST(MonomialOrder, AgreesWithTheDefinitionsOnRandomMonomials) {
  const std::size_t n = 5;
  testing::RandomSource random(31337);
  for (const auto& spec : specs(n)) {
    SCOPED_TRACE(spec.order.name());
    const RingPtr ring = Ring::make({"a", "b", "c", "d", "e"}, spec.order);
    for (int i = 0; i < 2000; ++i) {
      const Exponents a = random.exponents(n, 3), b = random.exponents(n, 3);
      ASSERT_EQ(compare(*ring, a, b), spec.reference(a, b))
          << ::testing::PrintToString(a) << " vs " << ::testing::PrintToString(b);
    }
  }
}

// The axioms: a total order, compatible with multiplication, with 1 the smallest
// monomial (so it is a well-order, which Buchberger's algorithm relies on).
TEST(MonomialOrder, IsAnAdmissibleTotalOrder) {
  const std::size_t n = 4;
  std::vector<MonomialOrder> orders = testing::all_orders(n);
  for (const auto& spec : specs(n)) orders.push_back(spec.order);
  testing::RandomSource random(4242);
  const Exponents one(n, 0);
  for (const MonomialOrder& order : orders) {
    SCOPED_TRACE(order.name());
    const RingPtr ring = Ring::make({"a", "b", "c", "d"}, order);
    std::vector<Exponents> monomials;
    for (int i = 0; i < 200; ++i) monomials.push_back(random.exponents(n, 4));
    for (int i = 0; i < 500; ++i) {
      const Exponents& a = monomials[random.uniform(0, 199)];
      const Exponents& b = monomials[random.uniform(0, 199)];
      const Exponents c = random.exponents(n, 3);
      const int ab = compare(*ring, a, b);
      EXPECT_EQ(ab, -compare(*ring, b, a));
      EXPECT_EQ(ab == 0, a == b);
      Exponents ac(n), bc(n);
      for (std::size_t k = 0; k < n; ++k) {
        ac[k] = a[k] + c[k];
        bc[k] = b[k] + c[k];
      }
      EXPECT_EQ(compare(*ring, ac, bc), ab);
      if (a != one) {
        EXPECT_EQ(compare(*ring, a, one), 1);
      }
      if (c != one) {
        EXPECT_EQ(compare(*ring, ac, a), 1);  // a properly divides ac
      }
    }
    // Transitivity: sorting with the order yields a chain consistent with every pair.
    std::sort(monomials.begin(), monomials.end(),
              [&](const Exponents& a, const Exponents& b) { return compare(*ring, a, b) > 0; });
    for (std::size_t i = 0; i + 1 < monomials.size(); ++i) {
      EXPECT_GE(compare(*ring, monomials[i], monomials[i + 1]), 0);
      EXPECT_GE(compare(*ring, monomials[i], monomials.back()), 0);
    }
  }
}

TEST(MonomialOrder, Names) {
  EXPECT_EQ(MonomialOrder::lex().name(), "lex");
  EXPECT_EQ(MonomialOrder::grlex().name(), "grlex");
  EXPECT_EQ(MonomialOrder::grevlex().name(), "grevlex");
  EXPECT_EQ(MonomialOrder::weighted({1, 2, 3}, MonomialOrder::grevlex()).name(), "weighted(1,2,3;grevlex)");
  EXPECT_EQ(MonomialOrder::block(2, MonomialOrder::grevlex(), MonomialOrder::lex()).name(), "block(2:grevlex|lex)");
}

TEST(MonomialOrder, SingularNames) {
  EXPECT_EQ(MonomialOrder::lex().singular_name(3), "lp");
  EXPECT_EQ(MonomialOrder::grlex().singular_name(3), "Dp");
  EXPECT_EQ(MonomialOrder::grevlex().singular_name(3), "dp");
  EXPECT_EQ(MonomialOrder::weighted({1, 2, 3}, MonomialOrder::grevlex()).singular_name(3), "(a(1,2,3),dp)");
  EXPECT_EQ(MonomialOrder::block(2, MonomialOrder::grevlex(), MonomialOrder::grevlex()).singular_name(5),
            "(dp(2),dp(3))");
  EXPECT_EQ(MonomialOrder::block(1, MonomialOrder::lex(), MonomialOrder::grlex()).singular_name(3), "(lp(1),Dp(2))");
}

TEST(MonomialOrder, FromName) {
  EXPECT_EQ(MonomialOrder::from_name("lex"), MonomialOrder::lex());
  EXPECT_EQ(MonomialOrder::from_name("grlex"), MonomialOrder::grlex());
  EXPECT_EQ(MonomialOrder::from_name("grevlex"), MonomialOrder::grevlex());
  EXPECT_TRUE(testing::throws_input_error([] { MonomialOrder::from_name("dp"); }, "unknown_order"));
  EXPECT_TRUE(testing::throws_input_error([] { MonomialOrder::from_name("Lex"); }, "unknown_order"));
}

TEST(MonomialOrder, DefaultIsGrevlex) {
  EXPECT_EQ(MonomialOrder(), MonomialOrder::grevlex());
  EXPECT_EQ(MonomialOrder().kind(), MonomialOrder::Kind::grevlex);
}

TEST(MonomialOrder, Equality) {
  EXPECT_FALSE(MonomialOrder::lex() == MonomialOrder::grlex());
  EXPECT_EQ(MonomialOrder::weighted({1, 2}, MonomialOrder::lex()),
            MonomialOrder::weighted({1, 2}, MonomialOrder::lex()));
  EXPECT_FALSE(MonomialOrder::weighted({1, 2}, MonomialOrder::lex()) ==
               MonomialOrder::weighted({1, 2}, MonomialOrder::grevlex()));
  EXPECT_FALSE(MonomialOrder::weighted({1, 2}, MonomialOrder::lex()) ==
               MonomialOrder::weighted({2, 1}, MonomialOrder::lex()));
  EXPECT_FALSE(MonomialOrder::block(1, MonomialOrder::lex(), MonomialOrder::lex()) ==
               MonomialOrder::block(2, MonomialOrder::lex(), MonomialOrder::lex()));
}

TEST(MonomialOrder, InvalidDescriptions) {
  EXPECT_TRUE(testing::throws_input_error(
      [] {
        MonomialOrder::weighted({1, -1}, MonomialOrder::lex());
      },
      "invalid_order"));
  EXPECT_TRUE(
      testing::throws_input_error([] { MonomialOrder::weighted({1025}, MonomialOrder::lex()); }, "invalid_order"));
  EXPECT_TRUE(testing::throws_input_error(
      [] {
        MonomialOrder::weighted({1, 2}, MonomialOrder::lex()).matrix(3);
      },
      "invalid_order"));
  EXPECT_TRUE(testing::throws_input_error(
      [] { MonomialOrder::block(4, MonomialOrder::lex(), MonomialOrder::lex()).matrix(3); }, "invalid_order"));
}

TEST(MonomialOrder, MatrixRows) {
  using Rows = std::vector<std::vector<std::int32_t>>;
  EXPECT_EQ(MonomialOrder::lex().matrix(2), (Rows{{1, 0}, {0, 1}}));
  EXPECT_EQ(MonomialOrder::grlex().matrix(3), (Rows{{1, 1, 1}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(MonomialOrder::grevlex().matrix(3), (Rows{{1, 1, 1}, {0, 0, -1}, {0, -1, 0}}));
  EXPECT_EQ(MonomialOrder::block(1, MonomialOrder::lex(), MonomialOrder::grevlex()).matrix(3),
            (Rows{{1, 0, 0}, {0, 1, 1}, {0, 0, -1}}));
  EXPECT_TRUE(MonomialOrder::grevlex().matrix(0).empty());
}

}  // namespace
}  // namespace implicitizer
