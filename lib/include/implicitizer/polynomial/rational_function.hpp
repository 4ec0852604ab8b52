#pragma once
/// \file
/// Quotients of polynomials, kept in lowest terms (gcd by FLINT), with a
/// denominator whose leading coefficient is positive. Used for rational
/// parametrizations.

#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// numerator / denominator with gcd 1, denominator != 0.
class RationalFunction {
 public:
  /// The polynomial p (denominator 1).
  explicit RationalFunction(Polynomial p);
  /// n / d in lowest terms; throws InputError (`division_by_zero`) if d = 0.
  RationalFunction(const Polynomial& n, const Polynomial& d);
  /// n / d for n and d known to be coprime (no gcd is taken, which for large n and d
  /// can cost more than building them); throws InputError (`division_by_zero`) if d = 0.
  static RationalFunction from_coprime(Polynomial n, Polynomial d);

  /// The numerator.
  const Polynomial& numerator() const { return numerator_; }
  /// The denominator (primitive integer polynomial, positive leading coefficient).
  const Polynomial& denominator() const { return denominator_; }
  /// Whether the denominator is a constant.
  bool is_polynomial() const { return denominator_.is_constant(); }

  /// this + o, its products checked against `budget` (Polynomial::multiply). The gcds
  /// are taken of the operands' denominators only (Henrici's sum), never of the result.
  RationalFunction add(const RationalFunction& o, const Budget& budget) const;
  /// this · o, its products checked against `budget`; the gcds are taken crosswise of
  /// the operands' numerators and denominators, never of the products.
  RationalFunction multiply(const RationalFunction& o, const Budget& budget) const;
  /// this / o as multiply(); throws InputError (`division_by_zero`) if `o` is 0.
  RationalFunction divide(const RationalFunction& o, const Budget& budget) const;
  /// add() without limits.
  RationalFunction operator+(const RationalFunction& o) const;
  RationalFunction operator-(const RationalFunction& o) const;
  /// multiply() without limits.
  RationalFunction operator*(const RationalFunction& o) const;
  /// divide() without limits.
  RationalFunction operator/(const RationalFunction& o) const;
  RationalFunction operator-() const;
  /// this^e, checked against `budget` (Polynomial::pow).
  RationalFunction pow(unsigned e, const Budget& budget = Budget()) const;

 private:
  // Makes the denominator primitive with a positive leading coefficient (its content
  // moves to the numerator); the denominator of 0 becomes 1.
  void normalize();

  Polynomial numerator_;
  Polynomial denominator_;
};

}  // namespace implicitizer
