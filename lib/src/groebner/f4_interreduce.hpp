#pragma once
// Private to the groebner module: the reduced basis modulo p of a Gröbner basis, by
// one Macaulay matrix (F4's final step). The rows are the minimal basis's elements
// and, from symbolic preprocessing (macaulay_rows.hpp), one multiple u·g for every
// monomial of a tail that a leading monomial divides; each element's tail is then
// eliminated left to right in a dense accumulator (f4_row_echelon.hpp). Its leading
// term stays: no other element's leading monomial divides it (the basis is minimal),
// and its own divides no monomial of its tail (they are smaller).
//
// Why a matrix: the polynomial interreduction (ModularArithmetic::reduce_basis)
// merges term lists at every step and builds a reducer list per element
// (docs/algorithms.md, "F4 modulo primes", item 8, has what it cost).

#include <cstdint>
#include <vector>

#include "f4_matrix.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "mod_polynomial.hpp"

namespace implicitizer::detail {

// The matrix of one interreduction without its coefficients: what symbolic
// preprocessing made of a minimal basis's supports. It depends on nothing else (the
// reducer of a monomial is chosen by the number of terms), so a basis modulo another
// prime with the same supports has the same matrix, and reduces by the plan to what
// reduce_basis_by_matrix would give, without the hashing and sorting of monomials.
// The multi-modular route records it on the prime it learns the trace on and
// replays it on the others (f4_trace.hpp; docs/algorithms.md, "F4 modulo primes",
// item 8, has what it saves).
class InterreductionPlan {
 public:
  // Whether a plan was recorded.
  bool empty() const { return element_rows_.empty(); }
  // Whether `minimal` (a minimal basis, sorted as ModularArithmetic::minimal_basis
  // gives it) has, element by element, the monomials the plan was recorded on.
  bool fits(const std::vector<ModPolynomial>& minimal) const;
  // The matrix's rows: the elements and the multiples symbolic preprocessing added.
  std::size_t rows() const { return rows_.size(); }

 private:
  friend std::vector<ModPolynomial> reduce_basis_by_matrix(const Ring&, const ModularArithmetic&,
                                                           std::vector<ModPolynomial>, const Budget&,
                                                           const InterreductionPlan*, InterreductionPlan*);
  std::vector<std::int32_t> supports_;     // the minimal basis's monomials, element after element
  std::vector<std::size_t> support_ends_;  // where each element ends in supports_ (in words)
  std::vector<MatrixRow> rows_;            // without coefficients
  std::vector<std::int64_t> pivot_;        // per column: its pivot's index in rows_, or −1
  std::vector<std::size_t> element_rows_;  // per element of the minimal basis, its row
  std::vector<std::int32_t> column_monomials_;
};

// What ModularArithmetic::reduce_basis gives (minimal, interreduced, monic, sorted by
// increasing leading monomial), for a Gröbner basis modulo arithmetic.prime().
// Checks `budget` as F4 does. With `replay`, when the minimal basis has the supports
// the plan was recorded on, by the plan; with `record`, the matrix made is recorded
// there (when the plan was not used).
std::vector<ModPolynomial> reduce_basis_by_matrix(const Ring& ring, const ModularArithmetic& arithmetic,
                                                  std::vector<ModPolynomial> basis, const Budget& budget,
                                                  const InterreductionPlan* replay = nullptr,
                                                  InterreductionPlan* record = nullptr);

}  // namespace implicitizer::detail
