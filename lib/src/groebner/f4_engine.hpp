#pragma once
// Private to the groebner module: the F4 driver modulo one prime (Faugère 1999). The
// pair queue and its criteria (Gebauer–Möller, product) are the Buchberger engine's
// (s_pair_queue.hpp); what differs is that all pairs of the lowest degree (or sugar)
// are reduced at once, as rows of one Macaulay matrix (f4_matrix.hpp) put in
// row-echelon form (f4_row_echelon.hpp).
//
// Why the result is a Gröbner basis: every selected S-polynomial is a combination of
// the matrix's rows, and the echelon form's rows together with the basis span the
// same space; the rows whose leading monomial is new join the basis, so every
// selected S-polynomial reduces to zero modulo the enlarged basis (Faugère's
// Theorem 2.4 and Corollary). Pairs the criteria drop reduce to zero by
// Buchberger's criteria, as in the Buchberger engine. When no pair is left the basis
// satisfies Buchberger's criterion.

#include <vector>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/f4.hpp"
#include "mod_polynomial.hpp"

namespace implicitizer::detail {

class F4Trace;
class InterreductionPlan;

// What an F4 run leaves: the unit ideal, or a Gröbner basis (minimal: no leading
// monomial divides another's; neither interreduced nor sorted).
struct F4Outcome {
  bool unit = false;
  std::vector<ModPolynomial> basis;
};

// F4 on `generators` (monic, modulo arithmetic.prime()) in `ring`. The pair
// selection follows params.variant.strategy (sugar, or the lcm's total degree for the
// normal strategy), the criteria params.variant's product and chain criteria;
// tail_reduce is implied (matrix rows are fully reduced by the pivots). Counts pairs,
// criteria, rows reduced and work in `stats`. Throws LimitExceeded from params.budget.
// With `learn`, the run's path is recorded there for replays on other primes
// (f4_trace.hpp). `threads` share each large matrix's echelon step
// (reduce_to_row_echelon): for a run that has the machine to itself.
F4Outcome run_f4(const Ring& ring, const ModularArithmetic& arithmetic, std::vector<ModPolynomial> generators,
                 const BuchbergerParams& params, BuchbergerStats& stats, F4Trace* learn = nullptr,
                 std::size_t threads = 1);

// The same outcome by `algorithm`: run_f4 (with `threads`), or the Buchberger engine
// modulo p (defined in f4.cpp, beside the public entry point).
F4Outcome run_modular_algorithm(const Ring& ring, const ModularArithmetic& arithmetic,
                                std::vector<ModPolynomial> generators, ModularAlgorithm algorithm,
                                const BuchbergerParams& params, BuchbergerStats& stats, std::size_t threads = 1);

// The reduced basis of a Gröbner basis modulo p, as `algorithm` makes it: by one
// Macaulay matrix after F4 (f4_interreduce.hpp), by polynomial reduction after
// Buchberger (ModularArithmetic::reduce_basis). Defined in f4.cpp.
// With F4, `replay` and `record` are reduce_basis_by_matrix's (f4_interreduce.hpp).
std::vector<ModPolynomial> reduce_modular_basis(const Ring& ring, const ModularArithmetic& arithmetic,
                                                std::vector<ModPolynomial> basis, ModularAlgorithm algorithm,
                                                const Budget& budget, const InterreductionPlan* replay = nullptr,
                                                InterreductionPlan* record = nullptr);

}  // namespace implicitizer::detail
