#pragma once
// Private to the groebner module: polynomials with coefficients in ℤ/p for a prime
// p < 2^63, the domain of the modular Buchberger runs (modular_groebner.cpp). Every
// polynomial this arithmetic returns is monic, so a reduction step is
// f ← f − lc(f)·m·g with no division, and a reduced basis modulo p is unique.

#include <flint/nmod.h>

#include <cstdint>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "int_polynomial.hpp"
#include "reducer.hpp"

namespace implicitizer::detail {

// Terms strictly decreasing, coefficients in [1, p), the leading one 1 (or empty).
struct ModPolynomial {
  std::vector<std::uint64_t> coefficients;
  std::vector<std::int32_t> monomials;  // monomial_size words per term

  std::size_t size() const { return coefficients.size(); }
  bool empty() const { return coefficients.empty(); }
};

// Arithmetic in (ℤ/p)[ring's variables], a domain of BuchbergerEngine.
class ModularArithmetic {
 public:
  using Polynomial = ModPolynomial;

  ModularArithmetic(const Ring& ring, std::uint64_t prime);

  std::uint64_t prime() const { return modulus_.n; }
  const nmod_t& modulus() const { return modulus_; }

  // p reduced modulo the prime and made monic; empty when p vanishes there.
  ModPolynomial reduce_coefficients(const IntPolynomial& p) const;
  // The S-polynomial of monic f and g: (L/lm f)·f − (L/lm g)·g, made monic.
  ModPolynomial s_polynomial(const ModPolynomial& f, const ModPolynomial& g) const;
  // f reduced by `reducers` (leading terms only, or every term with `full`), monic.
  ModPolynomial reduce(ModPolynomial f, const std::vector<BasicReducer<ModPolynomial>>& reducers, bool full,
                       const Budget& budget, ReductionCounters& counters, std::int32_t* sugar = nullptr) const;
  // The reduced basis of the ideal of the Gröbner basis `basis`: minimal,
  // interreduced, monic, sorted by increasing leading monomial.
  std::vector<ModPolynomial> reduce_basis(std::vector<ModPolynomial> basis, const Budget& budget) const;
  // The minimal basis of the Gröbner basis `basis` (no leading monomial divides
  // another's), sorted by increasing leading monomial, not interreduced.
  std::vector<ModPolynomial> minimal_basis(std::vector<ModPolynomial> basis) const;

 private:
  void make_monic(ModPolynomial& f) const;
  // out ← f[from_f..] − c·(shift·g)[from_g..], merged in decreasing order.
  void subtract_multiple(const ModPolynomial& f, std::size_t from_f, std::uint64_t c, const std::int32_t* shift,
                         const ModPolynomial& g, std::size_t from_g, ModPolynomial& out) const;

  const Ring& ring_;
  nmod_t modulus_;
};

}  // namespace implicitizer::detail
