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

  /// The numerator.
  const Polynomial& numerator() const { return numerator_; }
  /// The denominator (primitive integer polynomial, positive leading coefficient).
  const Polynomial& denominator() const { return denominator_; }
  /// Whether the denominator is a constant.
  bool is_polynomial() const { return denominator_.is_constant(); }

  RationalFunction operator+(const RationalFunction& o) const;
  RationalFunction operator-(const RationalFunction& o) const;
  RationalFunction operator*(const RationalFunction& o) const;
  /// Throws InputError (`division_by_zero`) if `o` is 0.
  RationalFunction operator/(const RationalFunction& o) const;
  RationalFunction operator-() const;
  /// this^e.
  RationalFunction pow(unsigned e, const Budget& budget = Budget()) const;

 private:
  Polynomial numerator_;
  Polynomial denominator_;
};

}  // namespace implicitizer
