#include "rational_proof.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>

#include "growing_basis.hpp"
#include "implicitizer/modular/one_per_thread.hpp"
#include "limb_row.hpp"
#include "macaulay_rows.hpp"
#include "s_pair_queue.hpp"

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "the proof over Q";

// A row is divided by the gcd of its entries only once its entries have outgrown the
// candidate's largest coefficient this many times over (in bits), and again each time
// they double after that. A scaling multiplies every entry by a factor, but the next
// pivot's multiple breaks that common factor, so the content is seldom more than a
// small number: dividing it out every 8 scaled steps cost more than it saved (docs/
// algorithms.md, "F4 modulo primes", item 7). The threshold bounds the growth where
// it would run away.
constexpr std::size_t kContentGrowth = 8;

// Reduction steps of one row between two budget checks (time, memory, cancellation;
// the work allowance is charged at every step).
constexpr std::size_t kStepsBetweenChecks = 64;

// One polynomial to check: the S-polynomial of basis elements i and j, or generator i.
struct Check {
  bool is_pair = false;
  std::size_t i = 0, j = 0;
};

// A row of a degree's matrix: basis element `poly` times a monomial, by column.
struct ProofRow {
  std::size_t poly = 0;
  std::vector<std::uint32_t> columns;  // increasing (monomials decreasing)
};

// One degree's matrix: the multiples of basis elements, the pivot of each column,
// and each check as rows (a pair: its two halves; a generator: its own columns).
struct ProofMatrix {
  std::vector<ProofRow> rows;
  std::vector<std::int64_t> pivot_of;                         // per column: index into rows, or -1
  std::vector<std::size_t> first_half, second_half;           // per check (pairs)
  std::vector<std::vector<std::uint32_t>> generator_columns;  // per check (generators)
};

ProofMatrix build_proof_matrix(const Ring& ring, const std::vector<IntPolynomial>& generators,
                               const std::vector<IntPolynomial>& basis,
                               const std::vector<BasicReducer<IntPolynomial>>& reducers,
                               const std::vector<Check>& checks, const Budget& budget) {
  const std::size_t w = ring.monomial_size();
  RowCollector<IntPolynomial> collector(ring, basis, budget, kWhere);
  ProofMatrix matrix;
  matrix.first_half.resize(checks.size());
  matrix.second_half.resize(checks.size());
  matrix.generator_columns.resize(checks.size());
  std::vector<std::int32_t> lcm(w), shift(w);
  for (std::size_t k = 0; k < checks.size(); ++k) {
    const Check& check = checks[k];
    if (check.is_pair) {
      const IntPolynomial& f = basis[check.i];
      const IntPolynomial& g = basis[check.j];
      ring.lcm(f.monomials.data(), g.monomials.data(), lcm.data());
      ring.divide(lcm.data(), f.monomials.data(), shift.data());
      matrix.first_half[k] = collector.add(check.i, shift.data());
      ring.divide(lcm.data(), g.monomials.data(), shift.data());
      matrix.second_half[k] = collector.add(check.j, shift.data());
    } else {
      const IntPolynomial& h = generators[check.i];
      budget.check_terms(h.size(), kWhere);
      for (std::size_t t = 0; t < h.size(); ++t) {
        matrix.generator_columns[k].push_back(collector.table().insert(h.monomials.data() + t * w));
      }
    }
  }
  collector.add_reducers(reducers);
  const std::vector<std::uint32_t> column_of = number_columns(ring, collector.table()).of_id;
  const std::vector<std::int64_t> shortest = shortest_rows_by_lead(collector.rows(), column_of.size());
  matrix.pivot_of.assign(column_of.size(), -1);
  for (std::size_t id = 0; id < column_of.size(); ++id) matrix.pivot_of[column_of[id]] = shortest[id];
  for (const PendingRow& pending : collector.rows()) {
    ProofRow row;
    row.poly = pending.poly;
    // Multiplying by a monomial keeps the order: the columns come out increasing.
    for (const std::uint32_t id : pending.ids) row.columns.push_back(column_of[id]);
    matrix.rows.push_back(std::move(row));
  }
  for (auto& columns : matrix.generator_columns) {
    for (auto& id : columns) id = column_of[id];
  }
  return matrix;
}

// The bits of a nonzero integer: |x| < 2^bits(x).
double bits(mpz_srcptr x) { return static_cast<double>(mpz_sizeinbase(x, 2)); }

// An upper bound on log2(2^a + 2^b): the size of a sum from those of its terms. The
// margin covers the rounding of the two floating-point operations.
double log2_sum(double a, double b) {
  const double high = std::max(a, b);
  return high + std::log2(1.0 + std::exp2(std::min(a, b) - high)) + 1e-9;
}

// The accumulator for a candidate with large coefficients: one GMP integer per
// column, each as long as its own value. LimbRow gives every entry of a row the width
// of the longest, which gains nothing once the entries run to thousands of bits and
// differ in size, and takes more memory (kLimbRowCoefficientBits). An mpz keeps its
// limbs when it is cleared, so a column reused costs no allocation.
class MpzRow {
 public:
  // How add_multiple takes the multiplied polynomials' coefficients.
  using Coefficients = std::vector<IntPolynomial>;

  void reserve_columns(std::size_t columns) {
    if (entries_.size() < columns) entries_.resize(columns);
  }
  std::size_t capacity_bits() const { return std::numeric_limits<std::size_t>::max(); }
  void ensure_bits(std::size_t) {}
  void reset_width(std::size_t) {}
  bool written(std::size_t c) const { return mpz_sgn(entries_[c].get_mpz_t()) != 0; }
  bool is_zero(std::size_t c) const { return !written(c); }
  void get(std::size_t c, mpz_ptr out) const { mpz_set(out, entries_[c].get_mpz_t()); }
  void set(std::size_t c, mpz_srcptr v) { mpz_set(entries_[c].get_mpz_t(), v); }
  void clear(std::size_t c) { mpz_set_ui(entries_[c].get_mpz_t(), 0); }
  void add_product(std::size_t c, mpz_srcptr f, mpz_srcptr m) { mpz_addmul(entries_[c].get_mpz_t(), f, m); }
  void add_multiple(const std::uint32_t* columns, std::size_t count, std::size_t from, mpz_srcptr f,
                    const std::vector<IntPolynomial>& polynomials, std::size_t i) {
    const std::vector<Integer>& values = polynomials[i].coefficients;
    for (std::size_t t = from; t < count; ++t) add_product(columns[t], f, values[t].get_mpz_t());
  }
  void multiply(std::size_t c, mpz_srcptr s) { mpz_mul(entries_[c].get_mpz_t(), entries_[c].get_mpz_t(), s); }
  std::size_t max_bits(std::size_t from, std::size_t to) const {
    std::size_t bits = 0;
    for (std::size_t c = from; c <= to && c < entries_.size(); ++c) {
      if (written(c)) bits = std::max(bits, mpz_sizeinbase(entries_[c].get_mpz_t(), 2));
    }
    return bits;
  }

 private:
  std::vector<Integer> entries_;
};

// Fraction-free elimination of one row over ℤ against a degree's pivots, in a dense
// accumulator `Row` (LimbRow or MpzRow) that is all zero before and, when the row
// reduces to zero, after. A LimbRow's entries have one width: the reducer keeps an
// upper bound on their size, from the sizes of what each step multiplies, and
// measures the entries only when that bound would pass the width (the bound is
// pessimistic: a step's multiple mostly cancels what it adds to), widening the row
// only when the measured size needs it. An MpzRow has no width to keep.
template <class Row>
class RowReducer {
 public:
  // `coefficients`: the basis's, as `Row` takes them; `poly_bits`: the bits of each
  // basis element's largest coefficient; `coefficient_bits`: of the basis's largest.
  RowReducer(const std::vector<IntPolynomial>& basis, const typename Row::Coefficients& coefficients,
             const std::vector<double>& poly_bits, std::size_t coefficient_bits, const Budget& budget)
      : basis_(basis),
        coefficients_(coefficients),
        poly_bits_(poly_bits),
        content_bits_(kContentGrowth * coefficient_bits + 64),
        budget_(budget) {}

  // Sizes the accumulator for a matrix of `columns` columns.
  void resize(std::size_t columns) { row_.reserve_columns(columns); }

  // fa·row_a − ga·row_b with fa, ga making the leading terms cancel: the
  // S-polynomial of a pair (both rows lead the same column).
  void load_pair(const ProofRow& a, const ProofRow& b) {
    const mpz_srcptr lc_a = basis_[a.poly].coefficients.front().get_mpz_t();
    const mpz_srcptr lc_b = basis_[b.poly].coefficients.front().get_mpz_t();
    mpz_gcd(gcd_.get_mpz_t(), lc_a, lc_b);
    mpz_divexact(scale_.get_mpz_t(), lc_b, gcd_.get_mpz_t());
    mpz_divexact(factor_.get_mpz_t(), lc_a, gcd_.get_mpz_t());
    mpz_neg(factor_.get_mpz_t(), factor_.get_mpz_t());
    bound_ = log2_sum(bits(scale_.get_mpz_t()) + poly_bits_[a.poly], bits(factor_.get_mpz_t()) + poly_bits_[b.poly]);
    row_.reset_width(static_cast<std::size_t>(std::ceil(bound_)));
    add_multiple(a, scale_.get_mpz_t(), 1);
    add_multiple(b, factor_.get_mpz_t(), 1);
    first_ = a.columns.front() + 1;
    last_ = std::max(a.columns.back(), b.columns.back());
  }

  // A generator's coefficients at its columns.
  void load_generator(const IntPolynomial& h, const std::vector<std::uint32_t>& columns) {
    std::size_t most = 0;
    for (const Integer& c : h.coefficients) most = std::max(most, mpz_sizeinbase(c.get_mpz_t(), 2));
    bound_ = static_cast<double>(most);
    row_.reset_width(most);
    for (std::size_t t = 0; t < columns.size(); ++t) row_.set(columns[t], h.coefficients[t].get_mpz_t());
    first_ = *std::min_element(columns.begin(), columns.end());
    last_ = *std::max_element(columns.begin(), columns.end());
  }

  // Eliminates the loaded row left to right; false at the first non-zero entry whose
  // column has no pivot (the row's normal form is not zero).
  bool reduces_to_zero(const ProofMatrix& matrix) {
    std::size_t steps = 0;
    std::size_t content_bits = content_bits_;
    const mpz_ptr lead = lead_.get_mpz_t();
    for (std::size_t c = first_; c <= last_; ++c) {
      if (row_.is_zero(c)) continue;
      const std::int64_t p = matrix.pivot_of[c];
      if (p < 0) {
        clear(c);
        return false;
      }
      const ProofRow& pivot = matrix.rows[static_cast<std::size_t>(p)];
      const mpz_srcptr lc = basis_[pivot.poly].coefficients.front().get_mpz_t();
      row_.get(c, lead);
      row_.clear(c);
      // row ← (lc/d)·row − (lead/d)·pivot, d = gcd(lead, lc).
      mpz_gcd(gcd_.get_mpz_t(), lead, lc);
      mpz_divexact(scale_.get_mpz_t(), lc, gcd_.get_mpz_t());
      mpz_divexact(factor_.get_mpz_t(), lead, gcd_.get_mpz_t());
      mpz_neg(factor_.get_mpz_t(), factor_.get_mpz_t());
      const bool scaled = mpz_cmp_ui(scale_.get_mpz_t(), 1) != 0;
      const double scale_bits = scaled ? bits(scale_.get_mpz_t()) : 0.0;
      const double added_bits = bits(factor_.get_mpz_t()) + poly_bits_[pivot.poly];
      double bound = log2_sum(bound_ + scale_bits, added_bits);
      if (bound > static_cast<double>(row_.capacity_bits())) {
        bound_ = static_cast<double>(row_.max_bits(c + 1, last_));
        bound = log2_sum(bound_ + scale_bits, added_bits);
        row_.ensure_bits(static_cast<std::size_t>(std::ceil(bound)));
      }
      std::uint64_t work = kWorkPerStep + kWorkPerTerm * pivot.columns.size();
      if (scaled) {
        for (std::size_t k = c + 1; k <= last_; ++k) {
          if (row_.written(k)) row_.multiply(k, scale_.get_mpz_t());
        }
        work += kWorkPerTerm * (last_ - c);
      }
      add_multiple(pivot, factor_.get_mpz_t(), 1);
      bound_ = bound;
      last_ = std::max<std::size_t>(last_, pivot.columns.back());
      budget_.charge_work(work, kWhere);
      if (scaled && mpz_sizeinbase(factor_.get_mpz_t(), 2) > content_bits) {
        remove_content(c + 1);
        content_bits *= 2;
        ++content_divisions_;
      }
      if (++steps % kStepsBetweenChecks == 0) budget_.check(kWhere);
    }
    return true;
  }

  // The divisions of a row by its content this reducer made.
  std::size_t content_divisions() const { return content_divisions_; }

 private:
  // row += factor·(the pivot row's coefficients), from term `from` on.
  void add_multiple(const ProofRow& r, mpz_srcptr factor, std::size_t from) {
    row_.add_multiple(r.columns.data(), r.columns.size(), from, factor, coefficients_, r.poly);
  }

  void remove_content(std::size_t from) {
    const mpz_ptr g = gcd_.get_mpz_t();
    const mpz_ptr entry = lead_.get_mpz_t();
    mpz_set_ui(g, 0);
    for (std::size_t k = from; k <= last_ && mpz_cmp_ui(g, 1) != 0; ++k) {
      if (!row_.written(k)) continue;
      row_.get(k, entry);
      mpz_gcd(g, g, entry);
    }
    if (mpz_cmp_ui(g, 1) <= 0) return;
    for (std::size_t k = from; k <= last_; ++k) {
      if (!row_.written(k)) continue;
      row_.get(k, entry);
      mpz_divexact(entry, entry, g);
      row_.set(k, entry);
    }
    bound_ = static_cast<double>(row_.max_bits(from, last_));
  }

  // Zeroes the accumulator from column `from` on (a refuted row leaves entries).
  void clear(std::size_t from) {
    for (std::size_t k = from; k <= last_; ++k) row_.clear(k);
  }

  const std::vector<IntPolynomial>& basis_;
  const typename Row::Coefficients& coefficients_;
  const std::vector<double>& poly_bits_;
  std::size_t content_bits_;  // the entries' bits above which the content is first divided out
  const Budget& budget_;
  Row row_;
  double bound_ = 0;  // log2 of an upper bound on the entries' magnitudes
  std::size_t first_ = 0, last_ = 0;
  std::size_t content_divisions_ = 0;
  Integer gcd_, scale_, factor_, lead_;
};

// The checks grouped by degree, the degrees in increasing order and the checks
// numbered one after the other, so that threads take them from one counter. A
// degree's matrix is built once: by the first thread that needs it, or ahead of time
// by the first thread to reach the degree before it, while the others still reduce
// (no thread waits for a matrix unless the degree before has no check left to take).
// It is freed when its last check is done.
class DegreeSchedule {
 public:
  using Builder = std::function<ProofMatrix(const std::vector<Check>&)>;

  DegreeSchedule(const std::map<std::int32_t, std::vector<Check>>& by_degree, Builder build)
      : degrees_(by_degree.size()), build_(std::move(build)) {
    std::size_t g = 0;
    for (const auto& degree_checks : by_degree) {
      degrees_[g].checks = &degree_checks.second;
      degrees_[g].first = total_;
      degrees_[g].left = degree_checks.second.size();
      total_ += degree_checks.second.size();
      ++g;
    }
  }

  std::size_t total() const { return total_; }

  // The degree of check k, searched from degree `from` on (the degree of the thread's
  // previous check: the counter only grows).
  std::size_t degree_of(std::size_t k, std::size_t from) const {
    while (k >= degrees_[from].first + degrees_[from].checks->size()) ++from;
    return from;
  }

  // Check k of degree g.
  const Check& check(std::size_t g, std::size_t k) const { return (*degrees_[g].checks)[k - degrees_[g].first]; }
  std::size_t index_in_degree(std::size_t g, std::size_t k) const { return k - degrees_[g].first; }

  // Degree g's matrix, built if it is not yet; the first thread here also builds the
  // next degree's. Valid until g's last check is done().
  const ProofMatrix& matrix(std::size_t g) {
    build(degrees_[g]);
    if (g + 1 < degrees_.size() && !degrees_[g + 1].claimed_ahead.exchange(true)) build(degrees_[g + 1]);
    return *degrees_[g].matrix;
  }

  // One check of degree g is done.
  void done(std::size_t g) {
    if (--degrees_[g].left == 0) degrees_[g].matrix.reset();
  }

 private:
  struct Degree {
    const std::vector<Check>* checks = nullptr;
    std::size_t first = 0;  // the number of its first check
    std::once_flag built;
    std::atomic<bool> claimed_ahead = false;
    std::unique_ptr<const ProofMatrix> matrix;
    std::atomic<std::size_t> left = 0;  // checks not done
  };

  void build(Degree& degree) {
    std::call_once(degree.built, [&] { degree.matrix = std::make_unique<const ProofMatrix>(build_(*degree.checks)); });
  }

  std::vector<Degree> degrees_;  // never resized: a Degree cannot move
  std::size_t total_ = 0;
  Builder build_;
};

// The bits of each element's largest coefficient.
std::vector<double> coefficient_bits_by_element(const std::vector<IntPolynomial>& basis) {
  std::vector<double> bits(basis.size(), 0.0);
  for (std::size_t i = 0; i < basis.size(); ++i) {
    for (const auto& c : basis[i].coefficients) {
      bits[i] = std::max(bits[i], static_cast<double>(mpz_sizeinbase(c.get_mpz_t(), 2)));
    }
  }
  return bits;
}

// What the threads' checks found.
struct ChecksRun {
  bool refuted = false;
  std::size_t content_divisions = 0;
};

// Runs every check of `schedule` on `workers` threads, each with its own accumulator
// row; the first refutation stops them all.
template <class Row>
ChecksRun run_checks(DegreeSchedule& schedule, const std::vector<IntPolynomial>& generators,
                     const std::vector<IntPolynomial>& basis, const typename Row::Coefficients& coefficients,
                     const std::vector<double>& poly_bits, std::size_t coefficient_bits, const Budget& budget,
                     std::size_t workers) {
  std::atomic<bool> stop = false, refuted = false;
  std::atomic<std::size_t> next = 0;
  std::vector<RowReducer<Row>> reducers_per_thread;
  for (std::size_t t = 0; t < workers; ++t)
    reducers_per_thread.emplace_back(basis, coefficients, poly_bits, coefficient_bits, budget);
  run_one_per_thread(workers, [&](std::size_t t) {
    RowReducer<Row>& reducer = reducers_per_thread[t];
    std::size_t g = 0;
    try {
      for (std::size_t k; !stop.load(std::memory_order_relaxed) && (k = next.fetch_add(1)) < schedule.total();) {
        g = schedule.degree_of(k, g);
        const ProofMatrix& matrix = schedule.matrix(g);
        budget.check(kWhere);
        const Check& check = schedule.check(g, k);
        const std::size_t c = schedule.index_in_degree(g, k);
        reducer.resize(matrix.pivot_of.size());
        if (check.is_pair) {
          reducer.load_pair(matrix.rows[matrix.first_half[c]], matrix.rows[matrix.second_half[c]]);
        } else {
          reducer.load_generator(generators[check.i], matrix.generator_columns[c]);
        }
        if (!reducer.reduces_to_zero(matrix)) {
          refuted = true;
          stop = true;
        }
        schedule.done(g);
        if (t == 0) budget.report_step(kWhere, k, schedule.total());
      }
    } catch (...) {
      stop = true;  // the others stop at their next check; the error is rethrown
      throw;
    }
  });
  ChecksRun run;
  run.refuted = refuted;
  for (const RowReducer<Row>& reducer : reducers_per_thread) run.content_divisions += reducer.content_divisions();
  return run;
}

}  // namespace

// As the Buchberger engine would reduce them on a candidate whose every S-polynomial
// reduces to zero: then no element is added, so these are all its pairs.
std::vector<SPair> proof_pairs(const Ring& ring, const std::vector<std::int32_t>& leading_monomials,
                               const BuchbergerParams& params) {
  BuchbergerStats stats;
  SPairQueue queue(ring, params, stats);
  GrowingBasis<IntPolynomial> entries(ring, queue);
  // The criteria read leading monomials only (the sugar only orders the queue, and
  // every pair left is taken): one-term polynomials stand for the elements.
  const std::size_t w = ring.monomial_size();
  std::vector<IntPolynomial> leads(leading_monomials.size() / w);
  for (std::size_t i = 0; i < leads.size(); ++i) {
    leads[i].coefficients.emplace_back(1);
    leads[i].monomials.assign(leading_monomials.begin() + static_cast<long>(i * w),
                              leading_monomials.begin() + static_cast<long>((i + 1) * w));
  }
  entries.insert_generators(std::move(leads), params.budget, "the proof over Q (the pairs)");
  std::vector<SPair> pairs;
  for (SPair pair; queue.pop(entries.entries(), pair);) pairs.push_back(std::move(pair));
  return pairs;
}

ProofOutcome prove_groebner_basis(const Ring& ring, const std::vector<IntPolynomial>& generators,
                                  const std::vector<IntPolynomial>& basis, const BuchbergerParams& params,
                                  std::size_t threads, ProofRows rows, const std::vector<SPair>* given_pairs) {
  const Budget& budget = params.budget;
  std::vector<SPair> own_pairs;
  if (given_pairs == nullptr) {
    std::vector<std::int32_t> leading_monomials;
    const std::size_t w = ring.monomial_size();
    for (const IntPolynomial& g : basis) {
      leading_monomials.insert(leading_monomials.end(), g.monomials.begin(),
                               g.monomials.begin() + static_cast<long>(w));
    }
    own_pairs = proof_pairs(ring, leading_monomials, params);
  }
  const std::vector<SPair>& pairs = given_pairs != nullptr ? *given_pairs : own_pairs;
  std::vector<BasicReducer<IntPolynomial>> reducers;
  for (const auto& g : basis) reducers.push_back({&g, ring.divisor_mask(g.monomials.data()), 0});

  // The checks of one degree (of their leading monomial) share a matrix.
  std::map<std::int32_t, std::vector<Check>> by_degree;
  for (std::size_t i = 0; i < generators.size(); ++i) {
    if (!generators[i].empty()) by_degree[ring.total_degree(generators[i].monomials.data())].push_back({false, i, 0});
  }
  for (const SPair& pair : pairs) by_degree[pair.lcm_degree].push_back({true, pair.i, pair.j});
  DegreeSchedule schedule(by_degree, [&](const std::vector<Check>& checks) {
    return build_proof_matrix(ring, generators, basis, reducers, checks, budget);
  });

  ProofOutcome outcome;
  outcome.pairs = pairs.size();
  const std::size_t workers = std::min(std::max<std::size_t>(threads, 1), schedule.total());
  const std::vector<double> poly_bits = coefficient_bits_by_element(basis);
  const auto coefficient_bits =
      static_cast<std::size_t>(poly_bits.empty() ? 0.0 : *std::max_element(poly_bits.begin(), poly_bits.end()));
  const bool limbs = rows == ProofRows::limbs ||
                     (rows == ProofRows::by_coefficient_size && coefficient_bits <= kLimbRowCoefficientBits);
  ChecksRun run;
  if (limbs) {
    run = run_checks<LimbRow>(schedule, generators, basis, PackedCoefficients(basis), poly_bits, coefficient_bits,
                              budget, workers);
  } else {
    // MpzRow reads the coefficients term after term, each in its own block: copied
    // here, one after the other, they lie together in memory (a lifted candidate's
    // were made on the lift's threads, and its proof ran slower).
    const std::vector<IntPolynomial> compact(basis);
    run = run_checks<MpzRow>(schedule, generators, compact, compact, poly_bits, coefficient_bits, budget, workers);
  }
  outcome.content_divisions = run.content_divisions;
  outcome.proven = !run.refuted;
  return outcome;
}

}  // namespace implicitizer::detail
