#pragma once
/// \file
/// Sparse distributed polynomials over ℚ.
///
/// Representation (FLINT's fmpq_mpoly layout): a rational content c times a
/// primitive integer polynomial P. Invariants, checked by `is_canonical()`:
///   - terms strictly decreasing in the ring's order, no zero coefficient;
///   - the integer coefficients of P have gcd 1 and P's leading coefficient is > 0;
///   - the zero polynomial has no terms and content 0.
/// Products of primitive polynomials are primitive (Gauss's lemma), so multiplying
/// needs no gcd; scaling by a rational touches only c.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer {

/// A polynomial with rational coefficients in a Ring.
class Polynomial {
 public:
  /// The zero polynomial of `ring`.
  explicit Polynomial(RingPtr ring);

  /// The constant `c`.
  static Polynomial constant(RingPtr ring, const Rational& c);
  /// The variable with index `index`.
  static Polynomial variable(RingPtr ring, std::size_t index);
  /// c·x^exponents (exponents has num_variables entries, each >= 0).
  static Polynomial term(RingPtr ring, const Rational& c, std::span<const std::int32_t> exponents);
  /// Builds content·Σ coefficients[i]·monomial i from terms in any order, possibly
  /// repeated (they are sorted and combined). `monomials` holds encoded monomials,
  /// monomial_size words each.
  static Polynomial from_terms(RingPtr ring, const Rational& content, std::vector<Integer> coefficients,
                               std::vector<std::int32_t> monomials);

  /// The ring.
  const RingPtr& ring() const { return ring_; }
  /// Number of terms.
  std::size_t num_terms() const { return coefficients_.size(); }
  /// Whether this is 0.
  bool is_zero() const { return coefficients_.empty(); }
  /// Whether this is a constant (0 included).
  bool is_constant() const;
  /// Rational coefficient of term i (terms are in decreasing order).
  Rational coefficient(std::size_t i) const;
  /// Encoded monomial of term i (see Ring).
  const std::int32_t* monomial(std::size_t i) const { return monomials_.data() + i * ring_->monomial_size(); }
  /// Exponent vector of term i.
  std::vector<std::int32_t> exponents(std::size_t i) const;
  /// The rational content c (sign included).
  const Rational& content() const { return content_; }
  /// Integer coefficients of the primitive part P.
  const std::vector<Integer>& integer_coefficients() const { return coefficients_; }
  /// All monomials, monomial_size words each, in decreasing order.
  const std::vector<std::int32_t>& monomial_data() const { return monomials_; }

  /// Leading coefficient; precondition: not zero.
  Rational leading_coefficient() const { return coefficient(0); }
  /// Leading monomial; precondition: not zero.
  const std::int32_t* leading_monomial() const { return monomial(0); }
  /// Total degree (-1 for zero).
  std::int32_t total_degree() const;
  /// Degree in variable `var` (-1 for zero).
  std::int32_t degree_in(std::size_t var) const;
  /// Whether the variable `var` occurs.
  bool involves(std::size_t var) const { return degree_in(var) > 0; }
  /// One flag per variable of the ring: whether it occurs.
  std::vector<bool> occurring_variables() const;

  Polynomial operator-() const;
  Polynomial operator+(const Polynomial& other) const;
  Polynomial operator-(const Polynomial& other) const;
  Polynomial operator*(const Polynomial& other) const;
  Polynomial& operator+=(const Polynomial& other) { return *this = *this + other; }
  Polynomial& operator-=(const Polynomial& other) { return *this = *this - other; }
  Polynomial& operator*=(const Polynomial& other) { return *this = *this * other; }
  /// Product checked against `budget`: refused before it is built when its number of
  /// terms is known in advance (one factor a monomial, or no variable shared) and
  /// passes the term limit; otherwise refused while it grows, within a few thousand
  /// terms of the limit; time, memory and cancellation checked as it grows.
  Polynomial multiply(const Polynomial& other, const Budget& budget) const;
  /// this^exponent, checked against `budget`: refused before it is built when its
  /// number of terms is known in advance (the binomial count C(m − 1 + e, e) of m
  /// terms whose exponent vectors are affinely independent, e.g. any two terms) and
  /// passes the term limit; otherwise each multiplication is checked as it grows.
  Polynomial pow(unsigned exponent, const Budget& budget = Budget()) const;
  /// this·c.
  Polynomial scaled(const Rational& c) const;
  /// this / c; throws InputError (`division_by_zero`) if c = 0.
  Polynomial divided_by(const Rational& c) const;

  /// ∂/∂x_var.
  Polynomial derivative(std::size_t var) const;
  /// The value at `point` (num_variables entries).
  Rational evaluate(std::span<const Rational> point) const;
  /// Replaces x_var by `value` (same ring).
  Polynomial substitute(std::size_t var, const Polynomial& value, const Budget& budget = Budget()) const;
  /// Composition: replaces variable i by values[i] (one per variable, all in `target`).
  Polynomial compose(const RingPtr& target, std::span<const Polynomial> values,
                     const Budget& budget = Budget()) const;
  /// Moves this into `target`, variable i becoming target variable var_map[i].
  Polynomial map_to(const RingPtr& target, std::span<const std::size_t> var_map) const;
  /// Homogenizes with variable `var` (which must not occur): every term is
  /// multiplied by x_var^(d - deg) where d is the total degree.
  Polynomial homogenize(std::size_t var) const;

  /// The primitive integer polynomial ±P with positive leading coefficient
  /// (the contract's form of an implicit equation); zero stays zero.
  Polynomial primitive_part() const;
  /// This divided by its leading coefficient; zero stays zero.
  Polynomial monic() const;

  /// Equality of polynomials in equal rings.
  bool operator==(const Polynomial& other) const;

  /// Checks every invariant listed in the file comment (for tests).
  bool is_canonical() const;

 private:
  Polynomial(RingPtr ring, Rational content, std::vector<Integer> coefficients, std::vector<std::int32_t> monomials);
  // Restores the invariants after the coefficients were changed but stay sorted.
  void normalize();
  // multiply() after its checks: Johnson's heap, `known_terms` (0: unknown) reserved.
  Polynomial multiply_johnson(const Polynomial& other, const Budget& budget, std::size_t known_terms) const;
  friend class PolynomialAccess;

  RingPtr ring_;
  Rational content_;
  std::vector<Integer> coefficients_;
  std::vector<std::int32_t> monomials_;
};

/// Multiplies every polynomial of `polynomials` by one positive integer, the lcm of
/// their contents' denominators, so that all coefficients become integers: what the
/// modular algorithms need, and harmless where only the polynomials' ratios matter
/// (a parametrization over a common denominator, a resultant up to a constant).
void scale_to_integers(std::span<Polynomial> polynomials);

/// Whether some variable occurs in both `a` and `b` (same ring).
bool share_a_variable(const Polynomial& a, const Polynomial& b);

/// The sum of `parts` (all in `ring`), added pairwise so that long sums cost
/// O(total · log count) instead of O(total · count).
Polynomial sum_of(const RingPtr& ring, std::vector<Polynomial> parts);

}  // namespace implicitizer
