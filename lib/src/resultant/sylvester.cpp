#include "implicitizer/resultant/sylvester.hpp"

#include <stdexcept>
#include <utility>

#include "implicitizer/polynomial/gcd.hpp"

namespace implicitizer {

std::vector<Polynomial> coefficients_in(const Polynomial& f, std::size_t var) {
  const RingPtr& ring = f.ring();
  if (var >= ring->num_variables()) throw std::invalid_argument("coefficients_in: no variable with that index");
  if (f.is_zero()) return {};
  const std::size_t w = ring->monomial_size();
  const std::size_t degree = static_cast<std::size_t>(f.degree_in(var));
  // One bucket of terms per power of x; the terms of a bucket are re-encoded with
  // x's exponent cleared (the key words depend on every exponent) and sorted by
  // from_terms. The primitive part's coefficients carry over; f's content is shared.
  std::vector<std::vector<Integer>> coefficients(degree + 1);
  std::vector<std::vector<std::int32_t>> monomials(degree + 1);
  std::vector<std::int32_t> exponents(ring->num_variables());
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::int32_t* e = ring->exponents(f.monomial(t));
    exponents.assign(e, e + ring->num_variables());
    const auto power = static_cast<std::size_t>(exponents[var]);
    exponents[var] = 0;
    coefficients[power].push_back(f.integer_coefficients()[t]);
    std::vector<std::int32_t>& bucket = monomials[power];
    bucket.resize(bucket.size() + w);
    ring->encode(exponents.data(), bucket.data() + bucket.size() - w);
  }
  std::vector<Polynomial> out;
  out.reserve(degree + 1);
  for (std::size_t i = 0; i <= degree; ++i) {
    out.push_back(Polynomial::from_terms(ring, f.content(), std::move(coefficients[i]), std::move(monomials[i])));
  }
  return out;
}

PolynomialMatrix sylvester_matrix(const Polynomial& f, const Polynomial& g, std::size_t var) {
  if (!(*f.ring() == *g.ring())) throw std::invalid_argument("sylvester_matrix: polynomials from different rings");
  if (f.is_zero() || g.is_zero()) {
    throw std::invalid_argument("sylvester_matrix: the zero polynomial has no degree, hence no Sylvester matrix");
  }
  const std::vector<Polynomial> fc = coefficients_in(f, var);
  const std::vector<Polynomial> gc = coefficients_in(g, var);
  const std::size_t m = fc.size() - 1;
  const std::size_t n = gc.size() - 1;
  PolynomialMatrix matrix(f.ring(), m + n, m + n);
  // Row r < n is x^(n-1-r)·f and row n + r is x^(m-1-r)·g, written in the basis
  // x^(m+n-1), …, 1: the coefficient of x^i sits in column m+n-1-i.
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t i = 0; i <= m; ++i) matrix.set(r, r + (m - i), fc[i]);
  }
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t j = 0; j <= n; ++j) matrix.set(n + r, r + (n - j), gc[j]);
  }
  return matrix;
}

Polynomial determinant_bareiss(const PolynomialMatrix& matrix, const Budget& budget) {
  if (!matrix.is_square()) throw std::invalid_argument("determinant_bareiss: the matrix is not square");
  const RingPtr& ring = matrix.ring();
  const std::size_t n = matrix.rows();
  if (n == 0) return Polynomial::constant(ring, Rational(1));
  PolynomialMatrix a = matrix;
  bool negate = false;
  Polynomial previous_pivot = Polynomial::constant(ring, Rational(1));
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (a.at(k, k).is_zero()) {
      std::size_t pivot_row = k + 1;
      while (pivot_row < n && a.at(pivot_row, k).is_zero()) ++pivot_row;
      // Column k is zero from row k down: after the earlier steps that makes the
      // matrix singular (those rows are k+1-minors with a zero column).
      if (pivot_row == n) return Polynomial(ring);
      a.swap_rows(k, pivot_row);
      negate = !negate;
    }
    const Polynomial& pivot = a.at(k, k);
    for (std::size_t i = k + 1; i < n; ++i) {
      for (std::size_t j = k + 1; j < n; ++j) {
        Polynomial cross = pivot.multiply(a.at(i, j), budget) - a.at(i, k).multiply(a.at(k, j), budget);
        a.set(i, j, divide_exact(cross, previous_pivot));
        budget.check_terms(a.at(i, j).num_terms(), "Bareiss determinant");
      }
      // Column k below the pivot is never read again; clearing it keeps the matrix
      // honest (upper triangular at the end) at no cost.
      a.set(i, k, Polynomial(ring));
    }
    previous_pivot = a.at(k, k);
  }
  Polynomial det = a.at(n - 1, n - 1);
  return negate ? -det : det;
}

}  // namespace implicitizer
