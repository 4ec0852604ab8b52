#pragma once
// Private to the groebner module: the fraction-free working representation of the
// Buchberger driver. A polynomial is kept as a primitive integer polynomial (its
// rational content is irrelevant to the ideal), and reduction uses only integer
// multiplications: f ← (b/d)·f − (a/d)·m·g with a = lc f, b = lc g, d = gcd(a, b).
// docs/design.md records why this beats rational arithmetic.

#include <cstdint>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "reducer.hpp"

namespace implicitizer::detail {

// Terms strictly decreasing, no zero coefficient.
struct IntPolynomial {
  std::vector<Integer> coefficients;
  std::vector<std::int32_t> monomials;  // monomial_size words per term

  std::size_t size() const { return coefficients.size(); }
  bool empty() const { return coefficients.empty(); }
};

// The primitive part of p (content dropped).
IntPolynomial to_int_polynomial(const Polynomial& p);
// The polynomial with these terms, made monic.
Polynomial to_monic_polynomial(const RingPtr& ring, const IntPolynomial& p);
// Divides by the gcd of the coefficients and makes the leading coefficient positive.
void make_primitive(IntPolynomial& p);

using Reducer = BasicReducer<IntPolynomial>;

// Reduces f by `reducers` (first the shortest reducer whose leading monomial divides).
// With `full`, every term is reduced (normal form); otherwise only leading terms.
// Returns a primitive positive multiple of the remainder; `sugar` is raised to the
// sugar of the reduction steps taken.
IntPolynomial reduce(const Ring& ring, IntPolynomial f, const std::vector<Reducer>& reducers, bool full,
                     const Budget& budget, ReductionCounters& counters, std::int32_t* sugar = nullptr);

// The fraction-free S-polynomial (b/d)·(L/lm f)·f − (a/d)·(L/lm g)·g.
IntPolynomial s_polynomial(const Ring& ring, const IntPolynomial& f, const IntPolynomial& g);

// The fraction-free integers as a domain of BuchbergerEngine (buchberger_engine.hpp).
class IntegerArithmetic {
 public:
  using Polynomial = IntPolynomial;

  explicit IntegerArithmetic(const Ring& ring) : ring_(ring) {}

  IntPolynomial s_polynomial(const IntPolynomial& f, const IntPolynomial& g) const {
    return detail::s_polynomial(ring_, f, g);
  }
  IntPolynomial reduce(IntPolynomial f, const std::vector<Reducer>& reducers, bool full, const Budget& budget,
                       ReductionCounters& counters, std::int32_t* sugar) const {
    return detail::reduce(ring_, std::move(f), reducers, full, budget, counters, sugar);
  }

 private:
  const Ring& ring_;
};

}  // namespace implicitizer::detail
