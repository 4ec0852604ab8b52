#pragma once
// Private to the groebner module: F4 with a trace (Traverso 1988, "Gröbner trace
// algorithms"; the "learning" of Giac's and msolve's modular F4). The multi-modular
// route runs F4 once per prime on the same generators, and for all but finitely many
// primes every run takes the same path: the same pairs, the same matrices, the same
// rows reducing to zero. The first prime's run records that path; the others replay
// it with their own coefficients and skip what the record says is wasted:
//
// - the pair queue and its criteria (the steps' matrices are known),
// - symbolic preprocessing (each row is stored as basis index and columns),
// - every row that reduced to zero, and every pivot that no remaining row reaches
//   (on the classic ideals about four rows in five reduce to zero).
// - the symbolic preprocessing of the final interreduction (f4_interreduce.hpp),
//   when the basis has the learned prime's supports.
//
// A replay checks what it can: each step must produce new rows with the recorded
// leading columns, in order, or it gives up and the prime is run in full. What it
// cannot check is a skipped row that would not have reduced to zero modulo this
// prime; then its basis is wrong. That happens only for the finitely many primes on
// which the two runs differ, and the route never trusts a basis modulo p anyway: a
// candidate must agree with further primes and, by default, is proven over ℚ
// (modular_groebner.hpp); the driver drops the trace when a candidate is rejected.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "f4_engine.hpp"
#include "f4_interreduce.hpp"
#include "f4_matrix.hpp"
#include "f4_row_echelon.hpp"

namespace implicitizer::detail {

// The path of one F4 run: per step, the rows that mattered.
class F4Trace {
 public:
  // Called by the learning run before the first step: the non-zero generators it
  // starts from (the basis's first elements).
  void start(std::size_t generators) { generators_ = generators; }
  // One step: its matrix and what the echelon form found (before the new rows are
  // sorted and join the basis).
  void record_step(const Ring& ring, const MacaulayMatrix& matrix, const EchelonResult& echelon);
  // The end of the run: the indices of the elements of the minimal basis.
  void finish(std::vector<std::size_t> minimal_basis) {
    minimal_basis_ = std::move(minimal_basis);
    complete_ = true;
  }
  // Whether the learning run ended with a basis (not the unit ideal, not stopped).
  bool complete() const { return complete_; }

  // The final interreduction's matrix, recorded by the learning run's caller after
  // F4 (f4_interreduce.hpp), and replayed by the other primes': part of the path.
  InterreductionPlan& interreduction() { return interreduction_; }
  const InterreductionPlan& interreduction() const { return interreduction_; }

  // The run's outcome modulo `arithmetic`'s prime on `generators` (monic, the same
  // polynomials as the learning run's modulo another prime), or nullopt when the
  // replay leaves the recorded path. Charges and checks `budget` as F4 does; counts
  // rows and work in `stats`.
  std::optional<F4Outcome> replay(const Ring& ring, const ModularArithmetic& arithmetic,
                                  std::vector<ModPolynomial> generators, const Budget& budget,
                                  BuchbergerStats& stats) const;

 private:
  struct Row {
    std::size_t poly = 0;
    std::vector<std::uint32_t> columns;
  };
  struct Step {
    std::size_t columns = 0;
    std::vector<std::int32_t> column_monomials;
    std::vector<Row> pivots;
    std::vector<Row> to_reduce;            // the rows that gave new rows, in order
    std::vector<std::uint32_t> new_leads;  // the leading column of each new row, in order
  };

  std::size_t generators_ = 0;
  std::vector<Step> steps_;
  std::vector<std::size_t> minimal_basis_;
  InterreductionPlan interreduction_;
  bool complete_ = false;
};

}  // namespace implicitizer::detail
