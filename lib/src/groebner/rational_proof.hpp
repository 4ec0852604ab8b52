#pragma once
// Private to the groebner module: the proof over ℚ of a modular candidate
// (modular_groebner.hpp's file comment, (a) and (b)): every generator reduces to
// zero modulo the candidate, and so does the S-polynomial of every pair that
// Gebauer–Möller's update leaves.
//
// The reductions are done as F4 does them modulo p, over ℤ: the polynomials to check
// are grouped by the degree of their leading monomial, and each group gets one
// Macaulay matrix whose rows are the multiples u·g of candidate elements that
// symbolic preprocessing finds (macaulay_rows.hpp), one pivot per column. Each
// polynomial is then loaded into a dense row of GMP integers and eliminated left
// to right, fraction-free. Top-reducing with one fixed reducer per monomial is a
// reduction like any other: if the candidate is a Gröbner basis, every element of
// its ideal reduces to zero whichever reducers are chosen, and a reduction to zero
// is a standard representation. So a row that reaches a non-zero column without a
// pivot refutes the candidate, and rows that all vanish prove it.
//
// Why a matrix rather than polynomial reduction: the same pivot rows serve every
// polynomial of a degree, their monomials are multiplied and compared once (in
// symbolic preprocessing) instead of at every step, and a step is an integer
// update at a column index, not a merge of two sorted term lists that allocates
// a coefficient per term (docs/algorithms.md has the measurements).

#include <cstddef>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "int_polynomial.hpp"
#include "s_pair_queue.hpp"

namespace implicitizer::detail {

// What the proof found.
struct ProofOutcome {
  bool proven = false;
  std::size_t pairs = 0;              // S-pairs checked (those Gebauer–Möller's update leaves)
  std::size_t content_divisions = 0;  // divisions of a row by its content (its entries outgrew the coefficients)
};

// The accumulator rows reduce in: fixed-width limbs (limb_row.hpp) or one GMP
// integer per entry. by_coefficient_size takes the limbs for candidates whose largest
// coefficient has at most kLimbRowCoefficientBits bits, where they are faster, and
// GMP for larger ones (docs/algorithms.md, "F4 modulo primes", item 7, has the
// measurements behind the threshold); the others are for tests of each.
enum class ProofRows { by_coefficient_size, limbs, gmp };
inline constexpr std::size_t kLimbRowCoefficientBits = 1024;

// The S-pairs the proof checks on a candidate with these leading monomials
// (monomial_size words each, concatenated, in the candidate's order): those
// Gebauer–Möller's update and the product criterion leave. They depend on nothing
// else, so the multi-modular route computes them while the primes run.
std::vector<SPair> proof_pairs(const Ring& ring, const std::vector<std::int32_t>& leading_monomials,
                               const BuchbergerParams& params);

// Whether `basis` (primitive integer polynomials) is a Gröbner basis of an ideal
// containing `generators`, checked exactly; the checks are shared among `threads`
// threads and the first that fails stops them all. `pairs`, when given, must be
// proof_pairs of the basis's leading monomials. Budget stops name "the proof over Q".
ProofOutcome prove_groebner_basis(const Ring& ring, const std::vector<IntPolynomial>& generators,
                                  const std::vector<IntPolynomial>& basis, const BuchbergerParams& params,
                                  std::size_t threads, ProofRows rows = ProofRows::by_coefficient_size,
                                  const std::vector<SPair>* pairs = nullptr);

}  // namespace implicitizer::detail
