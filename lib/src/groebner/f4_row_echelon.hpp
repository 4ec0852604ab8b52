#pragma once
// Private to the groebner module: the sparse row-echelon step of F4. The rows to
// reduce are eliminated, one at a time, by the pivots of the Macaulay matrix and by the
// new rows found before them, in a dense accumulator row (the approach of Faugère's
// and msolve's F4 and of Giac: a dense row is cheap to index, and rows stay sparse in
// storage).
//
// Delayed reduction: for primes below 2^31 every product c·a of two residues is below
// p² < 2^62, so an accumulator entry is kept in [0, p²) with one comparison per update
// and reduced modulo p only when its column is reached — one division per column
// instead of one per product. Larger primes (up to 2^63) take FLINT's nmod
// multiplication on every update.

#include <flint/nmod.h>

#include <cstdint>
#include <vector>

#include "f4_matrix.hpp"
#include "implicitizer/core/budget.hpp"

namespace implicitizer::detail {

// What the elimination found: the rows whose leading column no pivot had (monic,
// owning their coefficients, each fully reduced by the pivots and by the new rows
// found before it), and the work done (Budget::charge_work units, also charged).
struct EchelonResult {
  std::vector<MatrixRow> new_rows;
  std::vector<std::size_t> sources;  // per new row, its index in matrix.to_reduce
  std::uint64_t work = 0;
};

// Reduces matrix.to_reduce; checks `budget` (time, memory, cancellation, work) every
// few rows and its term limit on every row produced. Throws LimitExceeded. With
// `threads` > 1, a large matrix's rows are first eliminated by its pivots on that
// many threads, then by the new rows on this one: the same result.
EchelonResult reduce_to_row_echelon(const MacaulayMatrix& matrix, const nmod_t& modulus, const Budget& budget,
                                    std::size_t threads = 1);

// `row` (monic) with every column after its leading one eliminated by `pivot` (per
// column, a monic row leading there, or nullptr); `acc` is a zero accumulator of
// the matrix's width and is left zero. The tail reduction of F4's final
// interreduction (f4_interreduce.hpp).
MatrixRow reduce_tail(const MatrixRow& row, const std::vector<const MatrixRow*>& pivot, std::vector<std::uint64_t>& acc,
                      const nmod_t& modulus);

}  // namespace implicitizer::detail
