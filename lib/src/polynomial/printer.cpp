#include "implicitizer/polynomial/printer.hpp"

#include <gmp.h>

#include <charconv>

namespace implicitizer {

namespace {

// Appends |x| in decimal: GMP writes the digits in place, no string of its own.
void append_magnitude(std::string& out, mpz_srcptr x) {
  const std::size_t at = out.size();
  out.resize(at + mpz_sizeinbase(x, 10) + 2);  // the digits, a sign GMP may write, the terminator
  mpz_get_str(out.data() + at, 10, x);
  std::size_t end = at;
  while (out[end] != '\0') ++end;
  if (out[at] == '-') out.erase(at, 1), --end;
  out.resize(end);
}

}  // namespace

std::string to_string(const Polynomial& p) {
  if (p.is_zero()) return "0";
  const Ring& ring = *p.ring();
  // Coefficient t is content·c_t with content = a/b in lowest terms: in lowest terms,
  // (c_t/g)·a / (b/g) with g = gcd(c_t, b), one gcd a term (the printed basis of a
  // Gröbner computation is monic, a = 1 and b the common denominator).
  const mpq_class content = to_mpq(p.content());
  mpz_srcptr a = content.get_num_mpz_t();
  mpz_srcptr b = content.get_den_mpz_t();
  const bool whole = mpz_cmp_ui(b, 1) == 0;
  const bool unit_numerator = mpz_cmpabs_ui(a, 1) == 0;
  mpz_class g, numerator, denominator;
  std::string out;
  char exponent[16];
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    mpz_srcptr c = p.integer_coefficients()[t].get_mpz_t();
    if (whole) {
      mpz_mul(numerator.get_mpz_t(), c, a);
    } else {
      mpz_gcd(g.get_mpz_t(), c, b);
      mpz_divexact(numerator.get_mpz_t(), c, g.get_mpz_t());
      if (!unit_numerator) {
        mpz_mul(numerator.get_mpz_t(), numerator.get_mpz_t(), a);
      } else if (mpz_sgn(a) < 0) {
        mpz_neg(numerator.get_mpz_t(), numerator.get_mpz_t());
      }
      mpz_divexact(denominator.get_mpz_t(), b, g.get_mpz_t());
    }
    if (mpz_sgn(numerator.get_mpz_t()) < 0) {
      out += '-';
    } else if (t > 0) {
      out += '+';
    }
    const bool over_one = whole || mpz_cmp_ui(denominator.get_mpz_t(), 1) == 0;
    const bool one = over_one && mpz_cmpabs_ui(numerator.get_mpz_t(), 1) == 0;
    const std::int32_t* e = ring.exponents(p.monomial(t));
    bool constant = true;
    for (std::size_t i = 0; i < ring.num_variables(); ++i) constant = constant && e[i] == 0;
    if (!one || constant) {
      append_magnitude(out, numerator.get_mpz_t());
      if (!over_one) {
        out += '/';
        append_magnitude(out, denominator.get_mpz_t());
      }
      if (!constant) out += '*';
    }
    bool first = true;
    for (std::size_t i = 0; i < ring.num_variables(); ++i) {
      if (e[i] == 0) continue;
      if (!first) out += '*';
      first = false;
      out += ring.variables()[i];
      if (e[i] > 1) {
        out += '^';
        const auto [end, error] = std::to_chars(exponent, exponent + sizeof exponent, e[i]);
        out.append(exponent, end);
      }
    }
  }
  return out;
}

std::string to_string(const RationalFunction& f) {
  const std::string n = to_string(f.numerator());
  if (f.is_polynomial() && f.denominator().leading_coefficient() == Rational(1)) return n;
  // A single-term numerator needs no parentheses (a/b·c/d is one product chain), a
  // denominator does unless it is a number: n/2*e would read as (n/2)·e.
  const std::string numerator = f.numerator().num_terms() > 1 ? "(" + n + ")" : n;
  const std::string d = to_string(f.denominator());
  return numerator + "/" + (f.denominator().is_constant() ? d : "(" + d + ")");
}

}  // namespace implicitizer
