#pragma once
/// \file
/// The number types. The public coefficient type is CGAL's GMP rational; inside,
/// polynomials keep a rational content times a primitive integer polynomial
/// (FLINT's fmpq_mpoly layout), with GMP's C++ integers (docs/design.md says why).

#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include <string>

namespace implicitizer {

/// An exact rational number: the public coefficient type.
using Rational = CGAL::Gmpq;
/// An exact integer, used inside polynomials and algorithms.
using Integer = mpz_class;

/// Returns `q` as a GMP C++ rational (exact copy).
mpq_class to_mpq(const Rational& q);
/// Returns `q` as a CGAL rational (exact copy).
Rational to_rational(const mpq_class& q);
/// The integer value of `q`; throws std::invalid_argument when q is not an integer.
Integer to_integer(const Rational& q);

/// Returns the integer `z` as a CGAL rational.
Rational to_rational(const Integer& z);
/// Prints `q` as `n` or `n/d` (lowest terms, sign on the numerator).
std::string to_string(const Rational& q);

/// The largest F <= q (F = float or double): a bound rounded outwards. Beyond F's
/// range the answer is ±infinity; the caller refuses it.
template <typename F>
F round_down(const Rational& q);
/// The smallest F >= q (F = float or double); +infinity beyond F's range.
template <typename F>
F round_up(const Rational& q);

}  // namespace implicitizer
