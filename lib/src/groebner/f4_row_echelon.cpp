#include "f4_row_echelon.hpp"

#include <algorithm>
#include <atomic>

#include "implicitizer/modular/one_per_thread.hpp"
#include "reducer.hpp"

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "F4 matrix reduction";

// Rows between two budget checks: a row of the largest matrices measured (cyclic-7)
// costs well under a millisecond, so a stop is noticed within a few milliseconds.
constexpr std::size_t kRowsPerCheck = 8;

// Rows to reduce times columns from which a matrix's rows are shared among threads:
// below it the work is too short for starting a thread to pay (docs/algorithms.md,
// "F4 modulo primes", item 3).
constexpr std::size_t kConcurrentCells = 60'000;

// Reduces the accumulator, loaded with `row`, from column `start` on: every column
// with a pivot is eliminated, the others are moved (reduced modulo p) into `out`.
// Leaves the accumulator zero. `kDelayed`: entries in [0, p²), else in [0, p). The
// scan ends after the last column the row or a pivot subtracted reaches: the
// accumulator is zero beyond (a basis element of low degree lies in the last
// columns, far from the end of one of high degree).
template <bool kDelayed>
std::uint64_t eliminate_dense(std::vector<std::uint64_t>& acc, const MatrixRow& row, std::uint32_t start,
                              const std::vector<const MatrixRow*>& pivot, const nmod_t& modulus, MatrixRow& out) {
  const std::uint64_t p = modulus.n;
  const std::uint64_t p2 = kDelayed ? p * p : 0;
  std::uint64_t terms = 0;
  std::size_t end = row.columns.back() + std::size_t{1};
  for (std::size_t c = start; c < end; ++c) {
    std::uint64_t v = acc[c];
    if (v == 0) continue;
    acc[c] = 0;
    if constexpr (kDelayed) NMOD_RED(v, v, modulus);
    if (v == 0) continue;
    const MatrixRow* r = pivot[c];
    if (r == nullptr) {
      out.columns.push_back(static_cast<std::uint32_t>(c));
      out.owned.push_back(v);
      continue;
    }
    // acc −= v·r, the pivot being monic: its leading column is the one just cleared.
    const std::size_t n = r->size();
    end = std::max<std::size_t>(end, r->columns.back() + std::size_t{1});
    const std::uint32_t* cols = r->columns.data();
    const std::uint64_t* coefs = r->coefficients;
    terms += n;
    if constexpr (kDelayed) {
      const std::uint64_t factor = p - v;
      for (std::size_t i = 1; i < n; ++i) {
        const std::uint64_t x = acc[cols[i]] + factor * coefs[i];
        acc[cols[i]] = x >= p2 ? x - p2 : x;
      }
    } else {
      // Shoup's multiplication: the factor is the same for the whole row, so its
      // precomputed quotient turns each product modulo p into two multiplications and
      // a correction, where nmod_mul needs a double-word product and a division step.
      const std::uint64_t factor = p - v;
      const std::uint64_t factor_quotient = n_mulmod_precomp_shoup(factor, p);
      for (std::size_t i = 1; i < n; ++i) {
        const std::uint64_t x = acc[cols[i]] + n_mulmod_shoup(factor, coefs[i], factor_quotient, p);
        acc[cols[i]] = x >= p ? x - p : x;
      }
    }
  }
  return terms;
}

// `row` loaded into the zero accumulator and eliminated from its leading column on
// (eliminate_dense, the delayed form for primes below 2^31); the work, as
// Budget::charge_work counts it.
std::uint64_t reduce_row(std::vector<std::uint64_t>& acc, const MatrixRow& row,
                         const std::vector<const MatrixRow*>& pivot, const nmod_t& modulus, MatrixRow& out) {
  for (std::size_t i = 0; i < row.size(); ++i) acc[row.columns[i]] = row.coefficients[i];
  const std::uint64_t terms = modulus.n < (std::uint64_t{1} << 31)
                                  ? eliminate_dense<true>(acc, row, row.lead(), pivot, modulus, out)
                                  : eliminate_dense<false>(acc, row, row.lead(), pivot, modulus, out);
  return kWorkPerStep + kWorkPerModularTerm * (terms + row.size());
}

void make_monic(MatrixRow& row, const nmod_t& modulus) {
  const std::uint64_t inverse = nmod_inv(row.owned.front(), modulus);
  for (auto& c : row.owned) c = nmod_mul(c, inverse, modulus);
  row.coefficients = row.owned.data();
}

// The rows to reduce, each eliminated by the matrix's pivots alone (not by the new
// rows): `threads` threads take the rows from one counter, each with its own
// accumulator. What is left of a row lies in columns without a pivot, reduced
// modulo p, in increasing order (empty when the row reduced to zero).
std::vector<MatrixRow> reduce_by_pivots(const MacaulayMatrix& matrix, const std::vector<const MatrixRow*>& pivot,
                                        const nmod_t& modulus, const Budget& budget, std::size_t threads,
                                        std::uint64_t& work) {
  std::vector<MatrixRow> partial(matrix.to_reduce.size());
  std::vector<std::uint64_t> work_per_thread(threads, 0);
  std::atomic<std::size_t> next = 0;
  std::atomic<bool> stop = false;
  run_one_per_thread(threads, [&](std::size_t t) {
    std::vector<std::uint64_t> acc(matrix.columns, 0);
    try {
      for (std::size_t k; !stop.load(std::memory_order_relaxed) && (k = next.fetch_add(1)) < partial.size();) {
        if (k % kRowsPerCheck == 0) budget.check(kWhere);
        if (t == 0) budget.report_step(kWhere, k, partial.size());
        const std::uint64_t row_work = reduce_row(acc, matrix.to_reduce[k], pivot, modulus, partial[k]);
        work_per_thread[t] += row_work;
        budget.charge_work(row_work, kWhere);
        partial[k].coefficients = partial[k].owned.data();
      }
    } catch (...) {
      stop = true;  // the others stop at their next row; the error is rethrown
      throw;
    }
  });
  for (const std::uint64_t w : work_per_thread) work += w;
  return partial;
}

}  // namespace

EchelonResult reduce_to_row_echelon(const MacaulayMatrix& matrix, const nmod_t& modulus, const Budget& budget,
                                    std::size_t threads) {
  EchelonResult result;
  std::vector<const MatrixRow*> pivot(matrix.columns, nullptr);
  for (const MatrixRow& r : matrix.pivots) pivot[r.lead()] = &r;
  // Reserved: the pivot table points into new_rows as rows are found.
  result.new_rows.reserve(matrix.to_reduce.size());
  // With threads, the rows are first eliminated by the matrix's pivots concurrently,
  // then one after the other by the new rows (which lie in columns without a pivot,
  // so that they bring no pivot's column back). Each new row is the same as
  // sequentially: row k's remainder by the pivots and the new rows before it, zero at
  // all their leading columns, is unique (a non-zero combination of rows with
  // distinct leading columns is non-zero at the leftmost of them).
  const bool concurrent =
      threads > 1 && matrix.to_reduce.size() > 1 && matrix.to_reduce.size() * matrix.columns >= kConcurrentCells;
  std::vector<MatrixRow> partial;
  if (concurrent) partial = reduce_by_pivots(matrix, pivot, modulus, budget, threads, result.work);
  const std::vector<MatrixRow>& rows = concurrent ? partial : matrix.to_reduce;
  std::vector<std::uint64_t> acc(matrix.columns, 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (k % kRowsPerCheck == 0) {
      budget.check(kWhere);
      if (!concurrent) budget.report_step(kWhere, k, rows.size());
    }
    const MatrixRow& row = rows[k];
    if (row.columns.empty()) continue;  // reduced to zero by the pivots
    MatrixRow out;
    const std::uint64_t work = reduce_row(acc, row, pivot, modulus, out);
    result.work += work;
    budget.charge_work(work, kWhere);
    if (out.columns.empty()) continue;
    budget.check_terms(out.size(), kWhere);
    make_monic(out, modulus);
    result.new_rows.push_back(std::move(out));
    result.sources.push_back(k);
    pivot[result.new_rows.back().lead()] = &result.new_rows.back();
  }
  return result;
}

MatrixRow reduce_tail(const MatrixRow& row, const std::vector<const MatrixRow*>& pivot, std::vector<std::uint64_t>& acc,
                      const nmod_t& modulus) {
  MatrixRow out;
  out.columns.push_back(row.lead());
  out.owned.push_back(1);
  for (std::size_t i = 1; i < row.size(); ++i) acc[row.columns[i]] = row.coefficients[i];
  eliminate_dense<false>(acc, row, row.lead() + 1, pivot, modulus, out);
  out.coefficients = out.owned.data();
  return out;
}

}  // namespace implicitizer::detail
