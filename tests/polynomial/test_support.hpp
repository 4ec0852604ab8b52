#pragma once
/// \file
/// Helpers shared by the polynomial tests: seeded random rationals and polynomials,
/// the orders every property test runs over, and an assertion for InputError.

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/monomial_order.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer::testing {

/// Succeeds when `f` throws InputError with `code` (and `position`, when given).
inline ::testing::AssertionResult throws_input_error(const std::function<void()>& f, const std::string& code,
                                                     std::optional<std::size_t> position = std::nullopt) {
  try {
    f();
  } catch (const InputError& e) {
    if (e.code() != code || (position && e.position() != position)) {
      auto failure = ::testing::AssertionFailure() << "expected " << code;
      if (position) failure << " at " << *position;
      failure << ", got " << e.code();
      if (e.position()) failure << " at " << *e.position();
      return failure << " (" << e.what() << ")";
    }
    if (std::string(e.what()).empty()) return ::testing::AssertionFailure() << code << " has an empty message";
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "no InputError thrown (expected " << code << ")";
}

/// Seeded source of random test data; the same seed gives the same data everywhere.
class RandomSource {
 public:
  explicit RandomSource(std::uint64_t seed) : engine_(seed) {}

  /// A uniform integer in [lo, hi].
  long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(engine_); }

  /// A random integer with up to `digits` decimal digits, never zero, random sign.
  Integer integer(int digits) {
    std::string s(static_cast<std::size_t>(uniform(1, digits)), '0');
    s[0] = static_cast<char>('1' + uniform(0, 8));
    for (std::size_t i = 1; i < s.size(); ++i) s[i] = static_cast<char>('0' + uniform(0, 9));
    Integer z(s, 10);
    return uniform(0, 1) ? z : Integer(-z);
  }

  /// A non-zero rational: mostly small, sometimes huge (~10^60) or tiny (~10^-60).
  Rational rational() {
    mpq_class q;
    switch (uniform(0, 5)) {
      case 0:
        q = mpq_class(integer(60), 1);
        break;
      case 1:
        q = mpq_class(uniform(0, 1) ? 1 : -1, abs(integer(60)) + 1);
        break;
      case 2:
        q = mpq_class(integer(40), abs(integer(40)) + 1);
        break;
      default:
        q = mpq_class(integer(2), uniform(1, 12));
        break;
    }
    q.canonicalize();
    if (q == 0) q = 1;
    return to_rational(q);
  }

  /// A polynomial with up to `max_terms` terms, exponents in [0, max_exponent].
  Polynomial polynomial(const RingPtr& ring, int max_terms = 6, int max_exponent = 4) {
    Polynomial p(ring);
    const long terms = uniform(0, max_terms);
    std::vector<std::int32_t> e(ring->num_variables());
    for (long t = 0; t < terms; ++t) {
      for (auto& x : e) x = static_cast<std::int32_t>(uniform(0, 1) ? uniform(0, max_exponent) : 0);
      p += Polynomial::term(ring, rational(), e);
    }
    return p;
  }

  /// A point with small rational coordinates.
  std::vector<Rational> point(std::size_t n) {
    std::vector<Rational> pt;
    for (std::size_t i = 0; i < n; ++i) {
      mpq_class q(uniform(-9, 9), uniform(1, 5));
      q.canonicalize();
      pt.push_back(to_rational(q));
    }
    return pt;
  }

  /// An exponent vector with entries in [0, max_exponent].
  std::vector<std::int32_t> exponents(std::size_t n, int max_exponent) {
    std::vector<std::int32_t> e(n);
    for (auto& x : e) x = static_cast<std::int32_t>(uniform(0, max_exponent));
    return e;
  }

  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

/// One instance of every kind of order for `n` variables (n >= 3), with nested
/// tie-breaks and blocks, for property tests.
inline std::vector<MonomialOrder> all_orders(std::size_t n) {
  std::vector<int> weights(n), zero_weights(n, 0);
  for (std::size_t i = 0; i < n; ++i) weights[i] = static_cast<int>((i * 7 + 3) % 5);
  zero_weights[n - 1] = 2;
  return {MonomialOrder::lex(),
          MonomialOrder::grlex(),
          MonomialOrder::grevlex(),
          MonomialOrder::weighted(weights, MonomialOrder::grevlex()),
          MonomialOrder::weighted(zero_weights, MonomialOrder::lex()),
          MonomialOrder::block(1, MonomialOrder::lex(), MonomialOrder::grevlex()),
          MonomialOrder::block(2, MonomialOrder::grevlex(), MonomialOrder::grlex()),
          MonomialOrder::block(n - 1, MonomialOrder::grlex(), MonomialOrder::lex())};
}

}  // namespace implicitizer::testing
